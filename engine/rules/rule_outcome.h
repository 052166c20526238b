#pragma once
// What the operator rules say for one context: the rules that fired, the bounds they put on each
// decision variable (with the rules behind them), the advice, and the contradictions.
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rules/rule_ast.h"

namespace mx {

// Bounds are closed; a value within 1e-9 * max(1, |bound|) of a bound satisfies it.
double ruleTolerance(double bound);
bool boundHolds(const Bound& bound, double value);

struct RuleRef {
  int line = 0;
  std::string text;  // the rule as written
};

// One fired constraint on a variable: the reason shown to the operator.
struct BoundReason {
  RuleRef rule;
  Bound bound;
  std::string message;  // the rule's `because` text, or ""
};

struct VariableBounds {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  std::optional<RuleRef> lowerRule;  // the rule that set `lower` (the tightest lower bound)
  std::optional<RuleRef> upperRule;
  std::vector<BoundReason> reasons;  // every fired constraint on the variable, in line order

  bool empty() const { return lower > upper + ruleTolerance(upper); }
  bool admits(double value) const;
};

struct RuleAdvice {
  RuleRef rule;
  std::optional<Bound> bound;  // absent for `advise "TEXT"`
  std::string message;         // the given text, or the bound written out ("speed_rpm <= 8000")

  bool followedBy(double value) const { return !bound || boundHolds(*bound, value); }
};

// Two constraint rules whose bounds on `variable` leave no admissible value.
struct RuleContradiction {
  std::string variable;
  RuleRef first;  // the earlier line
  Bound firstBound;
  RuleRef second;
  Bound secondBound;
  std::string message;  // "line 1 'speed_rpm <= 8000' contradicts line 2 'speed_rpm >= 9000': ..."
};

// A rule whose condition could not be decided because a path it tests is missing from the context
// (or holds a value of the other type). It does not fire.
struct UndeterminedRule {
  RuleRef rule;
  std::vector<std::string> paths;
};

struct RuleOutcome {
  std::vector<RuleRef> fired;                     // constraints and advice, in line order
  std::map<std::string, VariableBounds> bounds;   // fired constraints only
  std::vector<RuleAdvice> advice;                 // fired advice, in line order
  std::vector<RuleContradiction> contradictions;  // every conflicting pair of fired constraints
  std::vector<UndeterminedRule> undetermined;

  bool consistent() const { return contradictions.empty(); }
  bool firedLine(int line) const;
  // False only when a fired constraint excludes the value (always false for a contradictory variable).
  bool admits(const std::string& variable, double value) const;
  const VariableBounds* boundsOf(const std::string& variable) const;
  // The fired constraints that a point (variable -> value) breaks; variables absent from the point are
  // not checked.
  std::vector<BoundReason> violations(const std::map<std::string, double>& point) const;
};

}  // namespace mx
