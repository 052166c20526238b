#include "rules/rule_ast.h"

#include <charconv>
#include <limits>
#include <utility>

namespace mx {

const char* toString(CompareOp op) {
  switch (op) {
    case CompareOp::Less:
      return "<";
    case CompareOp::LessEq:
      return "<=";
    case CompareOp::Greater:
      return ">";
    case CompareOp::GreaterEq:
      return ">=";
    case CompareOp::Equal:
      return "==";
    case CompareOp::NotEqual:
      return "!=";
  }
  return "?";
}

const char* toString(BoundOp op) {
  switch (op) {
    case BoundOp::LessEq:
      return "<=";
    case BoundOp::GreaterEq:
      return ">=";
    case BoundOp::Equal:
      return "==";
  }
  return "?";
}

const char* toString(RuleKind kind) {
  return kind == RuleKind::Constraint ? "constraint" : "advice";
}

Condition makeComparison(Comparison c) {
  auto node = std::make_shared<ConditionNode>();
  node->kind = ConditionNode::Kind::Compare;
  node->comparison = std::move(c);
  return node;
}

Condition makeNot(Condition operand) {
  auto node = std::make_shared<ConditionNode>();
  node->kind = ConditionNode::Kind::Not;
  node->left = std::move(operand);
  return node;
}

namespace {
Condition makeBinary(ConditionNode::Kind kind, Condition left, Condition right) {
  auto node = std::make_shared<ConditionNode>();
  node->kind = kind;
  node->left = std::move(left);
  node->right = std::move(right);
  return node;
}
}  // namespace

Condition makeAnd(Condition left, Condition right) {
  return makeBinary(ConditionNode::Kind::And, std::move(left), std::move(right));
}

Condition makeOr(Condition left, Condition right) {
  return makeBinary(ConditionNode::Kind::Or, std::move(left), std::move(right));
}

std::string formatNumber(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

namespace {

// Binding strength: or < and < not < comparison.
int precedence(const ConditionNode& node) {
  switch (node.kind) {
    case ConditionNode::Kind::Or:
      return 1;
    case ConditionNode::Kind::And:
      return 2;
    case ConditionNode::Kind::Not:
      return 3;
    case ConditionNode::Kind::Compare:
      return 4;
  }
  return 0;
}

std::string valueText(const RuleValue& value) {
  if (const auto* number = std::get_if<double>(&value)) return formatNumber(*number);
  std::string text = "\"";
  for (char c : std::get<std::string>(value)) {
    if (c == '"' || c == '\\') text += '\\';
    text += c;
  }
  return text + "\"";
}

std::string operand(const Condition& child, int parentPrecedence) {
  std::string text = toString(child);
  return precedence(*child) < parentPrecedence ? "(" + text + ")" : text;
}

}  // namespace

std::string toString(const Condition& condition) {
  if (!condition) return "";
  const ConditionNode& node = *condition;
  switch (node.kind) {
    case ConditionNode::Kind::Compare:
      return node.comparison.path + " " + toString(node.comparison.op) + " " + valueText(node.comparison.value);
    case ConditionNode::Kind::Not:
      return "not " + operand(node.left, 3);
    case ConditionNode::Kind::And:
      return operand(node.left, 2) + " and " + operand(node.right, 2);
    case ConditionNode::Kind::Or:
      return operand(node.left, 1) + " or " + operand(node.right, 1);
  }
  return "";
}

double Bound::lower() const {
  return op == BoundOp::LessEq ? -std::numeric_limits<double>::infinity() : value;
}

double Bound::upper() const {
  return op == BoundOp::GreaterEq ? std::numeric_limits<double>::infinity() : value;
}

std::string Bound::toString() const {
  return variable + " " + mx::toString(op) + " " + formatNumber(value);
}

const Rule* RuleSet::findLine(int line) const {
  for (const Rule& rule : rules)
    if (rule.line == line) return &rule;
  return nullptr;
}

}  // namespace mx
