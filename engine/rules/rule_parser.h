#pragma once
// Recursive-descent parser of the operator rule language (grammar in docs/operator-rules.md).
// One rule per line; blank lines and '#' comments are skipped (line numbers still count them).
// Every error carries the line and column and says what was expected.
#include <string>
#include <vector>

#include "rules/rule_ast.h"
#include "rules/rule_error.h"
#include "rules/rule_schema.h"
#include "rules/rule_token.h"

namespace mx {

// Bounds on the rule text that keep parsing linear, evaluation cheap and the recursion shallow; an
// operator's rule is a line of a few dozen characters.
inline constexpr std::size_t kMaxRuleLineLength = 1000;  // bytes per rule line
inline constexpr int kMaxRuleNesting = 32;               // '(' and 'not' open at one point
inline constexpr std::size_t kMaxRuleLines = 1000;       // lines in one rule list

struct RuleParseResult {
  RuleSet rules;                  // the lines that parsed (a line with an error contributes no rule)
  std::vector<RuleError> errors;  // the first error of each bad line, in line order

  bool ok() const { return errors.empty(); }
};

// lines[i] is line i + 1.
RuleParseResult parseRules(const std::vector<std::string>& lines, const RuleSchema& schema = RuleSchema::standard());
// Splits on '\n' first.
RuleParseResult parseRuleText(const std::string& text, const RuleSchema& schema = RuleSchema::standard());
// Throws RuleSyntaxError listing every error.
RuleSet parseRulesOrThrow(const std::vector<std::string>& lines, const RuleSchema& schema = RuleSchema::standard());

class RuleParser {
 public:
  explicit RuleParser(const RuleSchema& schema) : schema_(schema) {}

  // Parses one line. Returns false with `error` set on an error; returns true with `isRule` false for
  // a blank or comment-only line.
  bool parseLine(const std::string& text, int line, Rule& rule, bool& isRule, RuleError& error);

 private:
  struct Failure {
    int column;
    std::string message;
  };

  const RuleToken& peek() const { return tokens_[pos_]; }
  const RuleToken& advance() { return tokens_[pos_ < tokens_.size() - 1 ? pos_++ : pos_]; }
  const RuleToken& previous() const { return tokens_[pos_ > 0 ? pos_ - 1 : 0]; }
  bool accept(RuleTokenKind kind);
  [[noreturn]] void fail(const RuleToken& at, std::string message) const;
  [[noreturn]] void failExpected(const std::string& what, const std::string& after) const;

  // Counts one level of '(' or 'not' for as long as it lives; fails past kMaxRuleNesting.
  class NestingLevel {
   public:
    NestingLevel(RuleParser& parser, const RuleToken& at);
    ~NestingLevel() { --parser_.depth_; }
    NestingLevel(const NestingLevel&) = delete;
    NestingLevel& operator=(const NestingLevel&) = delete;

   private:
    RuleParser& parser_;
  };

  void parseConsequence(Rule& rule);
  Bound parseBound();
  Condition parseOr();
  Condition parseAnd();
  Condition parseUnary();
  Condition parsePrimary();
  Condition parseComparison();

  const RuleSchema& schema_;
  std::vector<RuleToken> tokens_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace mx
