#include "rules/rule_lexer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <utility>

namespace mx {
namespace {

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
bool isIdentStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool isIdentChar(char c) {
  return isIdentStart(c) || isDigit(c);
}
bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

}  // namespace

// The columns are counted once per line: a column lookup per token stays O(1), so a long line lexes in
// linear time.
RuleLexer::RuleLexer(const std::string& text, int line) : text_(text), line_(line) {
  columns_.reserve(text.size() + 1);
  int column = 1;
  for (const char c : text) {
    columns_.push_back(column);
    const auto byte = static_cast<unsigned char>(c);
    if ((byte & 0xC0u) != 0x80u) ++column;  // UTF-8 continuation bytes do not start a column
  }
  columns_.push_back(column);
}

int RuleLexer::columnAt(std::size_t offset) const {
  return columns_[std::min(offset, text_.size())];
}

RuleError RuleLexer::errorAt(std::size_t offset, std::string message) const {
  return RuleError{line_, columnAt(offset), std::move(message)};
}

bool RuleLexer::lexNumber(std::size_t& i, RuleToken& token, RuleError& error) const {
  const std::size_t start = i;
  if (text_[i] == '-' || text_[i] == '+') ++i;
  while (i < text_.size()) {
    const char c = text_[i];
    const bool exponentSign = (c == '-' || c == '+') && (text_[i - 1] == 'e' || text_[i - 1] == 'E');
    if (!isIdentChar(c) && c != '.' && !exponentSign) break;
    ++i;
  }
  const std::string lexeme = text_.substr(start, i - start);
  const std::size_t skip = lexeme[0] == '+' ? 1 : 0;
  double value = 0.0;
  const char* first = lexeme.data() + skip;
  const char* last = lexeme.data() + lexeme.size();
  const auto [end, ec] = std::from_chars(first, last, value, std::chars_format::general);
  if (ec != std::errc() || end != last || !std::isfinite(value)) {
    error = errorAt(start, "bad number '" + lexeme + "'");
    return false;
  }
  token = RuleToken{RuleTokenKind::Number, lexeme, value, columnAt(start)};
  return true;
}

bool RuleLexer::lexString(std::size_t& i, RuleToken& token, RuleError& error) const {
  const std::size_t start = i++;
  std::string value;
  while (i < text_.size() && text_[i] != '"') {
    if (text_[i] == '\\' && i + 1 < text_.size() && (text_[i + 1] == '"' || text_[i + 1] == '\\')) ++i;
    value += text_[i++];
  }
  if (i >= text_.size()) {
    error = errorAt(start, "unterminated string: missing the closing '\"'");
    return false;
  }
  ++i;  // closing quote
  token = RuleToken{RuleTokenKind::String, std::move(value), 0.0, columnAt(start)};
  return true;
}

bool RuleLexer::lexName(std::size_t& i, RuleToken& token, RuleError& error) const {
  const std::size_t start = i;
  while (true) {
    while (i < text_.size() && isIdentChar(text_[i])) ++i;
    if (i >= text_.size() || text_[i] != '.') break;
    if (i + 1 >= text_.size() || !isIdentStart(text_[i + 1])) {
      error = errorAt(i + 1, "expected a name after '" + text_.substr(start, i + 1 - start) + "'");
      return false;
    }
    ++i;
  }
  std::string name = text_.substr(start, i - start);
  token = RuleToken{keywordKind(name), std::move(name), 0.0, columnAt(start)};
  return true;
}

bool RuleLexer::tokenize(std::vector<RuleToken>& tokens, RuleError& error) {
  tokens.clear();
  std::size_t i = 0;
  while (true) {
    while (i < text_.size() && isSpace(text_[i])) ++i;
    if (i >= text_.size() || text_[i] == '#') break;
    const char c = text_[i];
    const char next = i + 1 < text_.size() ? text_[i + 1] : '\0';
    RuleToken token;
    if (isDigit(c) || (c == '.' && isDigit(next)) || ((c == '-' || c == '+') && (isDigit(next) || next == '.'))) {
      if (!lexNumber(i, token, error)) return false;
    } else if (c == '"') {
      if (!lexString(i, token, error)) return false;
    } else if (isIdentStart(c)) {
      if (!lexName(i, token, error)) return false;
    } else {
      RuleTokenKind kind = RuleTokenKind::End;
      std::size_t length = 1;
      if (c == '(') {
        kind = RuleTokenKind::LParen;
      } else if (c == ')') {
        kind = RuleTokenKind::RParen;
      } else if (c == '<') {
        kind = next == '=' ? RuleTokenKind::LessEq : RuleTokenKind::Less;
        length = next == '=' ? 2 : 1;
      } else if (c == '>') {
        kind = next == '=' ? RuleTokenKind::GreaterEq : RuleTokenKind::Greater;
        length = next == '=' ? 2 : 1;
      } else if (c == '=' && next == '=') {
        kind = RuleTokenKind::Equal;
        length = 2;
      } else if (c == '!' && next == '=') {
        kind = RuleTokenKind::NotEqual;
        length = 2;
      } else if (c == '=') {
        error = errorAt(i, "unexpected '=': write '==' to compare");
        return false;
      } else {
        // Report the whole UTF-8 sequence of a non-ASCII character.
        std::size_t end = i + 1;
        while (end < text_.size() && (static_cast<unsigned char>(text_[end]) & 0xC0u) == 0x80u) ++end;
        error = errorAt(i, "unexpected character '" + text_.substr(i, end - i) + "'");
        return false;
      }
      token = RuleToken{kind, text_.substr(i, length), 0.0, columnAt(i)};
      i += length;
    }
    tokens.push_back(std::move(token));
  }
  tokens.push_back(RuleToken{RuleTokenKind::End, "", 0.0, columnAt(i)});
  return true;
}

}  // namespace mx
