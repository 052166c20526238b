#pragma once
// The tokens of one operator rule line (see docs/operator-rules.md).
#include <string>

namespace mx {

enum class RuleTokenKind {
  Name,       // an identifier or dotted path: tool.diameter_mm, speed_rpm, weight.c3
  Number,     // 10, 0.2, -1.5e3
  String,     // "Ti6Al4V" (text holds the decoded value)
  Less,       // <
  LessEq,     // <=
  Greater,    // >
  GreaterEq,  // >=
  Equal,      // ==
  NotEqual,   // !=
  LParen,
  RParen,
  If,
  Then,
  And,
  Or,
  Not,
  Advise,   // advise ACTION | advise "TEXT"
  Advice,   // ACTION advice "TEXT"
  Because,  // ACTION because "TEXT"
  End,      // end of the line (a '#' comment also ends it)
};

struct RuleToken {
  RuleTokenKind kind = RuleTokenKind::End;
  std::string text;     // the lexeme as written (decoded for strings)
  double number = 0.0;  // Number only
  int column = 0;       // 1-based, in code points

  bool is(RuleTokenKind k) const { return kind == k; }
  bool isComparison() const;
  // How an error message names the token: 'then', "Ti6Al4V", 'end of rule'.
  std::string describe() const;
};

// The keyword for a plain identifier, or Name.
RuleTokenKind keywordKind(const std::string& identifier);

}  // namespace mx
