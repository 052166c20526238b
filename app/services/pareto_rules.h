#pragma once
// Module VII operator rules (Rule 18) for `millexpert-cli pareto`: the project's "operator_rules"
// array (one rule per element; element i is line i + 1) evaluated against the project and the Pareto
// tool (docs/operator-rules.md, "In the project").
//   - parse errors and contradictions: ProjectError exit 2 ("operator_rules[i]: line L, column C: ...");
//   - fired constraints on the point variables (speed_rpm, depth_mm, feed_mm_per_tooth, mrr_cm3_s,
//     power_W, feed_velocity_mm_s) restrict the selection;
//   - fired constraints on weight.tol/mrr/surf/ros bound the Pareto weights: the weights are projected
//     onto {w on the simplex, lo_i <= w_i <= hi_i} (clamp w_i + lambda, one lambda for all, chosen so
//     that the sum is 1: the Euclidean projection).
#include <QJsonObject>
#include <QStringList>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "document/project.h"
#include "pareto/objective_table.h"
#include "pareto/pareto_selector.h"
#include "pareto/pareto_weights.h"
#include "rules/rule_ast.h"
#include "rules/rule_context.h"
#include "rules/rule_outcome.h"

namespace mx::app {

struct ParetoRules {
  RuleSet rules;
  RuleOutcome outcome;

  // True when a fired constraint bounds a point variable (the selection is restricted).
  bool restrictsPoint() const;
  bool restrictsWeights() const;
  bool admits(const ParetoPoint& p, int teeth) const;
};

// The context of docs/operator-rules.md (tool.*, material.*, operation.*, machine.*) for one tool.
RuleContext ruleContextFor(const Project& project, const ToolSpec& tool);

// Parses and evaluates the rules; ProjectError (exit 2) on a parse error or a contradiction.
ParetoRules evaluateParetoRules(const QStringList& texts, const Project& project, const ToolSpec& tool);

// The decision variables of a point, in the rules' units.
std::map<std::string, double> pointVariables(const ParetoPoint& p, int teeth);

// Projects w onto the simplex within the bounds that the `outcomes` fired on the variables `names`
// (w_i between the largest lower and the smallest upper bound of names[i] over all outcomes): clamp
// w_i + lambda, one lambda for all, chosen so that the sum is 1 (the Euclidean projection).
// ProjectError (exit 2) when the bounds leave no weights on the simplex.
std::vector<double> applyWeightBounds(const std::vector<const RuleOutcome*>& outcomes,
                                      const std::vector<std::string>& names, const std::vector<double>& w);
// The Pareto weights under the fired weight.tol/mrr/surf/ros bounds.
ParetoWeights applyWeightRules(const RuleOutcome& outcome, const ParetoWeights& w);

// Coarse selection (Rule 10.1) over the table points passing `admit`; nullopt when none passes.
std::optional<ParetoSelection> selectWhere(const ObjectiveTable& table, const ParetoWeights& w,
                                           const std::function<bool(const ParetoPoint&)>& admit);

// {"fired": [{"line","text","kind","reason"}], "advice": [{"line","text","message","followed"}],
//  "undetermined": [{"line","text","paths"}]}; "followed" is null for advice on no point variable.
QJsonObject rulesJson(const ParetoRules& rules, const ParetoPoint& chosen, int teeth);

}  // namespace mx::app
