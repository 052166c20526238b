#include "rules/rule_parser.h"

#include <utility>

#include "rules/rule_lexer.h"

namespace mx {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n\f\v");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r\n\f\v");
  return s.substr(first, last - first + 1);
}

// Built with append: GCC 12 reports a false -Wrestrict for `"'" + std::string(...)` at -O3.
std::string quoted(const std::string& text) {
  return std::string(1, '\'').append(text).append(1, '\'');
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

CompareOp compareOp(RuleTokenKind kind) {
  switch (kind) {
    case RuleTokenKind::Less:
      return CompareOp::Less;
    case RuleTokenKind::LessEq:
      return CompareOp::LessEq;
    case RuleTokenKind::Greater:
      return CompareOp::Greater;
    case RuleTokenKind::GreaterEq:
      return CompareOp::GreaterEq;
    case RuleTokenKind::NotEqual:
      return CompareOp::NotEqual;
    default:
      return CompareOp::Equal;
  }
}

}  // namespace

bool RuleParser::accept(RuleTokenKind kind) {
  if (!peek().is(kind)) return false;
  advance();
  return true;
}

void RuleParser::fail(const RuleToken& at, std::string message) const {
  throw Failure{at.column, std::move(message)};
}

void RuleParser::failExpected(const std::string& what, const std::string& after) const {
  fail(peek(), "expected " + what + (after.empty() ? "" : " after " + after) + ", got " + peek().describe());
}

RuleParser::NestingLevel::NestingLevel(RuleParser& parser, const RuleToken& at) : parser_(parser) {
  if (++parser_.depth_ > kMaxRuleNesting) {
    --parser_.depth_;
    parser_.fail(at, "nested too deeply: more than " + std::to_string(kMaxRuleNesting) +
                         " '(' and 'not' open at once; split the rule");
  }
}

bool RuleParser::parseLine(const std::string& text, int line, Rule& rule, bool& isRule, RuleError& error) {
  isRule = false;
  if (text.size() > kMaxRuleLineLength) {
    error = RuleError{line, static_cast<int>(kMaxRuleLineLength) + 1,
                      "rule is " + std::to_string(text.size()) + " characters long; at most " +
                          std::to_string(kMaxRuleLineLength) + " are allowed"};
    return false;
  }
  depth_ = 0;
  RuleLexer lexer(text, line);
  if (!lexer.tokenize(tokens_, error)) return false;
  pos_ = 0;
  if (peek().is(RuleTokenKind::End)) return true;  // blank or comment
  rule = Rule{};
  rule.line = line;
  rule.text = trim(text);
  try {
    if (accept(RuleTokenKind::If)) {
      if (peek().is(RuleTokenKind::Then) || peek().is(RuleTokenKind::End))
        fail(peek(), "expected a condition after 'if', got " + peek().describe());
      rule.condition = parseOr();
      if (!accept(RuleTokenKind::Then)) {
        const bool inside = peek().is(RuleTokenKind::RParen);
        failExpected(inside ? "'then' (this ')' has no matching '(')" : "'then', 'and' or 'or'", "the condition");
      }
    }
    parseConsequence(rule);
  } catch (const Failure& f) {
    error = RuleError{line, f.column, f.message};
    return false;
  }
  isRule = true;
  return true;
}

void RuleParser::parseConsequence(Rule& rule) {
  const bool conditional = rule.condition != nullptr;
  const std::string after = conditional ? "'then'" : "";
  if (accept(RuleTokenKind::Advise)) {
    rule.kind = RuleKind::Advice;
    if (peek().is(RuleTokenKind::String)) {
      rule.message = advance().text;
    } else {
      if (!peek().is(RuleTokenKind::Name)) failExpected("a decision variable or a \"text\"", "'advise'");
      rule.bound = parseBound();
    }
  } else {
    if (!peek().is(RuleTokenKind::Name)) {
      if (conditional)
        failExpected("a decision variable or 'advise'", after);
      else
        failExpected("'if', 'advise' or a decision variable", "");
    }
    rule.bound = parseBound();
  }
  if (rule.bound && (peek().is(RuleTokenKind::Advice) || peek().is(RuleTokenKind::Because))) {
    const RuleToken& clause = advance();
    if (clause.is(RuleTokenKind::Advice)) rule.kind = RuleKind::Advice;
    if (!peek().is(RuleTokenKind::String)) failExpected("a \"text\"", clause.describe());
    rule.message = advance().text;
    if (!peek().is(RuleTokenKind::End)) failExpected("end of rule", "the " + clause.text + " text");
  }
  if (!peek().is(RuleTokenKind::End)) {
    if (rule.bound && rule.message.empty())
      failExpected("end of rule, 'advice \"...\"' or 'because \"...\"'", quoted(rule.bound->toString()));
    failExpected("end of rule", "the advice text");
  }
}

Bound RuleParser::parseBound() {
  const RuleToken& name = advance();
  Bound bound;
  bound.variable = name.text;
  bound.column = name.column;
  if (!schema_.hasVariable(name.text)) {
    if (schema_.pathType(name.text))
      fail(name, quoted(name.text) +
                     " is a context path, not a decision variable; bound one of: " + joined(schema_.variables()));
    fail(name, "unknown decision variable '" + name.text + "' (one of: " + joined(schema_.variables()) + ")");
  }
  const RuleToken& op = peek();
  if (op.is(RuleTokenKind::LessEq)) {
    bound.op = BoundOp::LessEq;
  } else if (op.is(RuleTokenKind::GreaterEq)) {
    bound.op = BoundOp::GreaterEq;
  } else if (op.is(RuleTokenKind::Equal)) {
    bound.op = BoundOp::Equal;
  } else if (op.isComparison()) {
    fail(op, "a bound uses <=, >= or ==, got " + op.describe());
  } else {
    failExpected("<=, >= or ==", quoted(name.text));
  }
  advance();
  if (!peek().is(RuleTokenKind::Number)) failExpected("a number", quoted(name.text + " " + op.text));
  bound.value = advance().number;
  return bound;
}

Condition RuleParser::parseOr() {
  Condition left = parseAnd();
  while (accept(RuleTokenKind::Or)) left = makeOr(left, parseAnd());
  return left;
}

Condition RuleParser::parseAnd() {
  Condition left = parseUnary();
  while (accept(RuleTokenKind::And)) left = makeAnd(left, parseUnary());
  return left;
}

Condition RuleParser::parseUnary() {
  if (peek().is(RuleTokenKind::Not)) {
    const NestingLevel level(*this, advance());
    return makeNot(parseUnary());
  }
  return parsePrimary();
}

Condition RuleParser::parsePrimary() {
  if (peek().is(RuleTokenKind::LParen)) {
    const RuleToken& open = advance();
    const NestingLevel level(*this, open);
    const int openColumn = open.column;
    if (peek().is(RuleTokenKind::RParen)) fail(peek(), "expected a condition after '(', got ')'");
    Condition inner = parseOr();
    if (!accept(RuleTokenKind::RParen))
      failExpected("')' to close the '(' at column " + std::to_string(openColumn) + ", or 'and'/'or'", "");
    return inner;
  }
  if (peek().is(RuleTokenKind::Name)) return parseComparison();
  failExpected("a comparison such as 'tool.teeth >= 4', 'not' or '('", previous().describe());
}

Condition RuleParser::parseComparison() {
  const RuleToken& name = advance();
  Comparison c;
  c.path = name.text;
  c.column = name.column;
  const auto type = schema_.pathType(name.text);
  if (!type) {
    if (schema_.hasVariable(name.text))
      fail(name, quoted(name.text) + " is a decision variable; conditions test context paths (" +
                     schema_.describeNear("") + ")");
    fail(name, "unknown path '" + name.text + "' (known: " + schema_.describeNear(name.text) + ")");
  }
  const RuleToken& op = peek();
  if (!op.isComparison()) failExpected("a comparison operator (<, <=, >, >=, ==, !=)", quoted(name.text));
  advance();
  c.op = compareOp(op.kind);
  const bool ordering = c.op != CompareOp::Equal && c.op != CompareOp::NotEqual;
  if (*type == RuleValueType::String && ordering)
    fail(op, quoted(op.text) + " does not apply to the string path '" + name.text + "': use == or !=");
  const RuleToken& value = peek();
  if (value.is(RuleTokenKind::Number)) {
    if (*type == RuleValueType::String)
      fail(value, "type mismatch: '" + name.text + "' is a string, compared with the number " + value.text);
    c.value = value.number;
  } else if (value.is(RuleTokenKind::String)) {
    if (*type == RuleValueType::Number)
      fail(value, "type mismatch: '" + name.text + "' is a number, compared with the string " + value.describe());
    c.value = value.text;
  } else {
    failExpected(*type == RuleValueType::Number ? "a number" : "a \"string\"", quoted(name.text + " " + op.text));
  }
  advance();
  return makeComparison(std::move(c));
}

RuleParseResult parseRules(const std::vector<std::string>& lines, const RuleSchema& schema) {
  RuleParseResult result;
  if (lines.size() > kMaxRuleLines) {
    result.errors.push_back(RuleError{
        static_cast<int>(kMaxRuleLines) + 1, 1,
        std::to_string(lines.size()) + " rule lines; at most " + std::to_string(kMaxRuleLines) + " are allowed"});
    return result;
  }
  RuleParser parser(schema);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    Rule rule;
    bool isRule = false;
    RuleError error;
    if (!parser.parseLine(lines[i], static_cast<int>(i + 1), rule, isRule, error))
      result.errors.push_back(std::move(error));
    else if (isRule)
      result.rules.rules.push_back(std::move(rule));
  }
  return result;
}

RuleParseResult parseRuleText(const std::string& text, const RuleSchema& schema) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (true) {
    const auto end = text.find('\n', start);
    lines.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return parseRules(lines, schema);
}

RuleSet parseRulesOrThrow(const std::vector<std::string>& lines, const RuleSchema& schema) {
  RuleParseResult result = parseRules(lines, schema);
  if (!result.ok()) throw RuleSyntaxError(std::move(result.errors));
  return std::move(result.rules);
}

}  // namespace mx
