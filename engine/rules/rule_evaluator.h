#pragma once
// Evaluates operator rules against a context (Module VII, Rule 18).
//
// Conditions use three-valued logic: a comparison whose path is missing from the context (or holds a
// value of the other type) is unknown; `not unknown` is unknown, `false and unknown` is false,
// `true or unknown` is true. A rule fires only when its condition is true (unconditional rules always
// fire); rules left unknown are listed in RuleOutcome::undetermined with the paths they lacked.
//
// Fired constraints intersect into one closed interval per variable; every pair of fired constraints
// whose intervals are disjoint is a contradiction naming both lines (for intervals, the intersection is
// empty exactly when some pair is disjoint, so this list is complete). Advice never restricts.
#include <vector>

#include "rules/rule_ast.h"
#include "rules/rule_context.h"
#include "rules/rule_outcome.h"

namespace mx {

enum class Truth { False, True, Unknown };

Truth evaluateCondition(const Condition& condition, const RuleContext& context,
                        std::vector<std::string>* missingPaths = nullptr);

RuleOutcome evaluate(const RuleSet& rules, const RuleContext& context);

// Static check, independent of any context: pairs of constraint rules with disjoint bounds on one
// variable where both are unconditional (they contradict for every context), one is unconditional
// (they contradict whenever the other fires), or both conditions have the same canonical text.
std::vector<RuleContradiction> staticContradictions(const RuleSet& rules);

}  // namespace mx
