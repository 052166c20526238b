#include "rules/rule_evaluator.h"

#include <algorithm>

namespace mx {
namespace {

Truth fromBool(bool b) {
  return b ? Truth::True : Truth::False;
}

template <typename T>
bool compare(CompareOp op, const T& lhs, const T& rhs) {
  switch (op) {
    case CompareOp::Less:
      return lhs < rhs;
    case CompareOp::LessEq:
      return lhs <= rhs;
    case CompareOp::Greater:
      return lhs > rhs;
    case CompareOp::GreaterEq:
      return lhs >= rhs;
    case CompareOp::Equal:
      return lhs == rhs;
    case CompareOp::NotEqual:
      return lhs != rhs;
  }
  return false;
}

Truth evaluateComparison(const Comparison& c, const RuleContext& context, std::vector<std::string>* missing) {
  const RuleValue* actual = context.find(c.path);
  if (actual == nullptr || actual->index() != c.value.index()) {
    if (missing && std::find(missing->begin(), missing->end(), c.path) == missing->end()) missing->push_back(c.path);
    return Truth::Unknown;
  }
  if (const auto* number = std::get_if<double>(actual))
    return fromBool(compare(c.op, *number, std::get<double>(c.value)));
  return fromBool(compare(c.op, std::get<std::string>(*actual), std::get<std::string>(c.value)));
}

RuleRef refOf(const Rule& rule) {
  return RuleRef{rule.line, rule.text};
}

bool disjoint(const Bound& a, const Bound& b) {
  return a.lower() > b.upper() + ruleTolerance(b.upper()) || b.lower() > a.upper() + ruleTolerance(a.upper());
}

RuleContradiction contradiction(const Rule& a, const Rule& b, const std::string& why) {
  RuleContradiction c;
  c.variable = a.bound->variable;
  c.first = refOf(a);
  c.firstBound = *a.bound;
  c.second = refOf(b);
  c.secondBound = *b.bound;
  c.message = "line " + std::to_string(a.line) + " '" + a.bound->toString() + "' contradicts line " +
              std::to_string(b.line) + " '" + b.bound->toString() + "': " + why;
  return c;
}

bool isConstraint(const Rule& r) {
  return r.kind == RuleKind::Constraint && r.bound.has_value();
}

void addBound(VariableBounds& vb, const Rule& rule) {
  const Bound& b = *rule.bound;
  if (b.lower() > vb.lower) {
    vb.lower = b.lower();
    vb.lowerRule = refOf(rule);
  }
  if (b.upper() < vb.upper) {
    vb.upper = b.upper();
    vb.upperRule = refOf(rule);
  }
  vb.reasons.push_back(BoundReason{refOf(rule), b, rule.message});
}

}  // namespace

Truth evaluateCondition(const Condition& condition, const RuleContext& context, std::vector<std::string>* missing) {
  if (!condition) return Truth::True;
  const ConditionNode& node = *condition;
  switch (node.kind) {
    case ConditionNode::Kind::Compare:
      return evaluateComparison(node.comparison, context, missing);
    case ConditionNode::Kind::Not: {
      const Truth t = evaluateCondition(node.left, context, missing);
      return t == Truth::Unknown ? t : fromBool(t == Truth::False);
    }
    case ConditionNode::Kind::And: {
      const Truth l = evaluateCondition(node.left, context, missing);
      const Truth r = evaluateCondition(node.right, context, missing);
      if (l == Truth::False || r == Truth::False) return Truth::False;
      return l == Truth::True && r == Truth::True ? Truth::True : Truth::Unknown;
    }
    case ConditionNode::Kind::Or: {
      const Truth l = evaluateCondition(node.left, context, missing);
      const Truth r = evaluateCondition(node.right, context, missing);
      if (l == Truth::True || r == Truth::True) return Truth::True;
      return l == Truth::False && r == Truth::False ? Truth::False : Truth::Unknown;
    }
  }
  return Truth::Unknown;
}

RuleOutcome evaluate(const RuleSet& rules, const RuleContext& context) {
  RuleOutcome out;
  std::vector<const Rule*> firedConstraints;
  for (const Rule& rule : rules.rules) {
    std::vector<std::string> missing;
    const Truth t = evaluateCondition(rule.condition, context, &missing);
    if (t == Truth::Unknown) {
      out.undetermined.push_back(UndeterminedRule{refOf(rule), std::move(missing)});
      continue;
    }
    if (t == Truth::False) continue;
    out.fired.push_back(refOf(rule));
    if (isConstraint(rule)) {
      addBound(out.bounds[rule.bound->variable], rule);
      firedConstraints.push_back(&rule);
    } else {
      const std::string message =
          !rule.message.empty() ? rule.message : (rule.bound ? rule.bound->toString() : std::string());
      out.advice.push_back(RuleAdvice{refOf(rule), rule.bound, message});
    }
  }
  for (std::size_t i = 0; i < firedConstraints.size(); ++i)
    for (std::size_t j = i + 1; j < firedConstraints.size(); ++j) {
      const Rule& a = *firedConstraints[i];
      const Rule& b = *firedConstraints[j];
      if (a.bound->variable == b.bound->variable && disjoint(*a.bound, *b.bound))
        out.contradictions.push_back(contradiction(a, b, "no " + a.bound->variable + " satisfies both"));
    }
  return out;
}

std::vector<RuleContradiction> staticContradictions(const RuleSet& rules) {
  std::vector<RuleContradiction> out;
  for (std::size_t i = 0; i < rules.rules.size(); ++i)
    for (std::size_t j = i + 1; j < rules.rules.size(); ++j) {
      const Rule& a = rules.rules[i];
      const Rule& b = rules.rules[j];
      if (!isConstraint(a) || !isConstraint(b) || a.bound->variable != b.bound->variable) continue;
      if (!disjoint(*a.bound, *b.bound)) continue;
      if (a.unconditional() && b.unconditional()) {
        out.push_back(contradiction(a, b, "both are unconditional, so they contradict for every context"));
      } else if (a.unconditional() || b.unconditional()) {
        const Rule& conditional = a.unconditional() ? b : a;
        out.push_back(
            contradiction(a, b, "they contradict whenever line " + std::to_string(conditional.line) + " fires"));
      } else if (toString(a.condition) == toString(b.condition)) {
        out.push_back(contradiction(a, b, "they have the same condition, so they contradict whenever they fire"));
      }
    }
  return out;
}

}  // namespace mx
