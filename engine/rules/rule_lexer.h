#pragma once
// Splits one rule line into tokens. Whitespace separates tokens; '#' outside a string starts a
// comment that runs to the end of the line. Lexical errors (unterminated string, bad number,
// unexpected character) are returned as a RuleError with the line and column.
#include <optional>
#include <string>
#include <vector>

#include "rules/rule_error.h"
#include "rules/rule_token.h"

namespace mx {

class RuleLexer {
 public:
  RuleLexer(const std::string& text, int line);

  // The tokens, always ending with an End token; or the first lexical error of the line.
  bool tokenize(std::vector<RuleToken>& tokens, RuleError& error);

 private:
  int columnAt(std::size_t offset) const;
  RuleError errorAt(std::size_t offset, std::string message) const;
  bool lexNumber(std::size_t& i, RuleToken& token, RuleError& error) const;
  bool lexString(std::size_t& i, RuleToken& token, RuleError& error) const;
  bool lexName(std::size_t& i, RuleToken& token, RuleError& error) const;

  const std::string& text_;
  int line_;
  std::vector<int> columns_;  // 1-based column of each byte offset, and one past the end
};

}  // namespace mx
