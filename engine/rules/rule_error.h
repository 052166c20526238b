#pragma once
// Errors of the operator rule language (Module VII, Rule 18): a position in the rule text and a
// message. Lines and columns are 1-based; columns count Unicode code points of the line (a tab is one
// column), so an editor can place an inline marker directly.
#include <stdexcept>
#include <string>
#include <vector>

#include "core/invalid_input.h"

namespace mx {

struct RulePos {
  int line = 0;
  int column = 0;
};

struct RuleError {
  int line = 0;
  int column = 0;
  std::string message;  // without the position, e.g. "expected 'then' after the condition, got 'speed_rpm'"

  // "line 3, column 17: <message>"
  std::string toString() const;
};

// Thrown by parseRulesOrThrow when any line has an error; what() lists every error, one per line.
class RuleSyntaxError : public InvalidInput {
 public:
  explicit RuleSyntaxError(std::vector<RuleError> errors);
  const std::vector<RuleError>& errors() const { return errors_; }

 private:
  std::vector<RuleError> errors_;
};

}  // namespace mx
