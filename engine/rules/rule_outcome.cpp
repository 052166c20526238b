#include "rules/rule_outcome.h"

#include <algorithm>
#include <cmath>

namespace mx {

double ruleTolerance(double bound) {
  return 1e-9 * std::max(1.0, std::isfinite(bound) ? std::abs(bound) : 1.0);
}

bool boundHolds(const Bound& bound, double value) {
  const double tol = ruleTolerance(bound.value);
  switch (bound.op) {
    case BoundOp::LessEq:
      return value <= bound.value + tol;
    case BoundOp::GreaterEq:
      return value >= bound.value - tol;
    case BoundOp::Equal:
      return std::abs(value - bound.value) <= tol;
  }
  return false;
}

bool VariableBounds::admits(double value) const {
  if (std::isnan(value) || empty()) return false;
  return value >= lower - ruleTolerance(lower) && value <= upper + ruleTolerance(upper);
}

bool RuleOutcome::firedLine(int line) const {
  return std::any_of(fired.begin(), fired.end(), [line](const RuleRef& r) { return r.line == line; });
}

const VariableBounds* RuleOutcome::boundsOf(const std::string& variable) const {
  const auto it = bounds.find(variable);
  return it == bounds.end() ? nullptr : &it->second;
}

bool RuleOutcome::admits(const std::string& variable, double value) const {
  const VariableBounds* b = boundsOf(variable);
  return b == nullptr ? !std::isnan(value) : b->admits(value);
}

std::vector<BoundReason> RuleOutcome::violations(const std::map<std::string, double>& point) const {
  std::vector<BoundReason> out;
  for (const auto& [variable, vb] : bounds) {
    const auto it = point.find(variable);
    if (it == point.end()) continue;
    for (const BoundReason& reason : vb.reasons)
      if (!boundHolds(reason.bound, it->second)) out.push_back(reason);
  }
  std::sort(out.begin(), out.end(),
            [](const BoundReason& a, const BoundReason& b) { return a.rule.line < b.rule.line; });
  return out;
}

}  // namespace mx
