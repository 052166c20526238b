#include "rules/rule_token.h"

namespace mx {

bool RuleToken::isComparison() const {
  switch (kind) {
    case RuleTokenKind::Less:
    case RuleTokenKind::LessEq:
    case RuleTokenKind::Greater:
    case RuleTokenKind::GreaterEq:
    case RuleTokenKind::Equal:
    case RuleTokenKind::NotEqual:
      return true;
    default:
      return false;
  }
}

std::string RuleToken::describe() const {
  switch (kind) {
    case RuleTokenKind::End:
      return "end of rule";
    case RuleTokenKind::String:
      return "\"" + text + "\"";
    default:
      return std::string(1, '\'').append(text).append(1, '\'');  // not "'" + text: GCC 12 -Wrestrict
  }
}

RuleTokenKind keywordKind(const std::string& identifier) {
  if (identifier == "if") return RuleTokenKind::If;
  if (identifier == "then") return RuleTokenKind::Then;
  if (identifier == "and") return RuleTokenKind::And;
  if (identifier == "or") return RuleTokenKind::Or;
  if (identifier == "not") return RuleTokenKind::Not;
  if (identifier == "advise") return RuleTokenKind::Advise;
  if (identifier == "advice") return RuleTokenKind::Advice;
  if (identifier == "because") return RuleTokenKind::Because;
  return RuleTokenKind::Name;
}

}  // namespace mx
