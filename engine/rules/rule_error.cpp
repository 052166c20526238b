#include "rules/rule_error.h"

#include <utility>

namespace mx {

std::string RuleError::toString() const {
  return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + message;
}

namespace {
std::string joinErrors(const std::vector<RuleError>& errors) {
  std::string text;
  for (const RuleError& e : errors) {
    if (!text.empty()) text += '\n';
    text += e.toString();
  }
  return text.empty() ? std::string("invalid operator rules") : text;
}
}  // namespace

RuleSyntaxError::RuleSyntaxError(std::vector<RuleError> errors)
    : InvalidInput(joinErrors(errors)), errors_(std::move(errors)) {}

}  // namespace mx
