#pragma once
// The syntax tree of operator rules (Module VII, Rule 18). A RuleSet is immutable after parsing and
// cheap to copy (conditions are shared).
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace mx {

using RuleValue = std::variant<double, std::string>;

enum class CompareOp { Less, LessEq, Greater, GreaterEq, Equal, NotEqual };
enum class BoundOp { LessEq, GreaterEq, Equal };
enum class RuleKind { Constraint, Advice };

const char* toString(CompareOp op);
const char* toString(BoundOp op);
const char* toString(RuleKind kind);  // "constraint", "advice"

// `tool.diameter_mm < 10`, `material.name == "Ti6Al4V"`
struct Comparison {
  std::string path;
  CompareOp op = CompareOp::Equal;
  RuleValue value;
  int column = 0;  // of the path
};

struct ConditionNode;
using Condition = std::shared_ptr<const ConditionNode>;

struct ConditionNode {
  enum class Kind { Compare, Not, And, Or };
  Kind kind = Kind::Compare;
  Comparison comparison;  // Compare
  Condition left;         // Not (operand), And, Or
  Condition right;        // And, Or
};

Condition makeComparison(Comparison c);
Condition makeNot(Condition operand);
Condition makeAnd(Condition left, Condition right);
Condition makeOr(Condition left, Condition right);

// Canonical text, fully parenthesised where needed: `tool.teeth >= 4 and (a < 1 or b > 2)`.
std::string toString(const Condition& condition);
std::string formatNumber(double value);  // shortest text that reads back as the same double

// `speed_rpm <= 8000`
struct Bound {
  std::string variable;
  BoundOp op = BoundOp::LessEq;
  double value = 0.0;
  int column = 0;  // of the variable

  double lower() const;  // -inf for <=
  double upper() const;  // +inf for >=
  std::string toString() const;
};

struct Rule {
  int line = 0;                // 1-based line in the rule list
  std::string text;            // the line as written, trimmed
  Condition condition;         // null: unconditional
  std::optional<Bound> bound;  // absent only for message-only advice (`advise "TEXT"`)
  RuleKind kind = RuleKind::Constraint;
  std::string message;  // the advice / because text ("" when not given)

  bool unconditional() const { return condition == nullptr; }
};

struct RuleSet {
  std::vector<Rule> rules;  // in line order; blank and comment lines are not rules

  bool empty() const { return rules.empty(); }
  std::size_t size() const { return rules.size(); }
  const Rule* findLine(int line) const;
};

}  // namespace mx
