// Fuzz target of the operator rules (Rule 18, docs/operator-rules.md): parseRuleText, then evaluation
// on a fixed context, then the canonical text. A bad line is a RuleError with its line and column and
// contributes no rule; nothing throws. The rules that parse keep their promises: evaluation gives
// bounds that are never NaN, a variable's bounds are empty exactly when a contradiction names it,
// and each rule written in canonical form (toString of its condition and bound) parses again to the
// same rule.
#include <cstdint>
#include <set>
#include <string>

#include "fuzz_check.h"
#include "rules/rule_evaluator.h"
#include "rules/rule_parser.h"

namespace {

using mx::fuzz::require;

// Longer canonical texts are left out of the round trip: written fully, a rule may outgrow the
// parser's 1000-byte line limit.
constexpr std::size_t kCanonicalLineBudget = 900;

// Every documented path but machine.name (a missing path makes comparisons unknown).
const mx::RuleContext& fixedContext() {
  static const mx::RuleContext kContext = [] {
    mx::RuleContext c;
    double number = 0.5;
    for (const std::string& path : mx::RuleSchema::standard().paths()) {
      if (path == "machine.name") continue;
      if (mx::RuleSchema::standard().pathType(path) == mx::RuleValueType::String)
        c.set(path, path == "operation.milling" ? "down" : "Ti6Al4V");
      else
        c.set(path, number *= 3.0);
    }
    return c;
  }();
  return kContext;
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char ch : text) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + '"';
}

std::string canonicalText(const mx::Rule& rule) {
  std::string text = rule.condition ? "if " + mx::toString(rule.condition) + " then " : "";
  if (!rule.bound) return text + "advise " + quoted(rule.message);
  if (rule.kind == mx::RuleKind::Advice)
    return text + (rule.message.empty() ? "advise " + rule.bound->toString()
                                        : rule.bound->toString() + " advice " + quoted(rule.message));
  return text + rule.bound->toString() + (rule.message.empty() ? "" : " because " + quoted(rule.message));
}

void checkCanonicalText(const mx::Rule& rule) {
  const std::string text = canonicalText(rule);
  if (text.size() > kCanonicalLineBudget) return;
  const mx::RuleParseResult again = mx::parseRuleText(text);
  if (!again.ok()) std::fprintf(stderr, "fuzz: '%s': %s\n", text.c_str(), again.errors.front().message.c_str());
  require(again.ok() && again.rules.size() == 1, "a rule's canonical text parses");
  const mx::Rule& r = again.rules.rules.front();
  require(r.kind == rule.kind && r.message == rule.message && r.bound.has_value() == rule.bound.has_value(),
          "the canonical text keeps the kind and the message");
  require(!r.bound || (r.bound->toString() == rule.bound->toString() && r.bound->value == rule.bound->value),
          "the canonical text keeps the bound");
  require((r.condition == nullptr) == (rule.condition == nullptr) &&
              (!r.condition || mx::toString(r.condition) == mx::toString(rule.condition)),
          "the canonical text keeps the condition");
}

void checkOutcome(const mx::RuleSet& rules) {
  const mx::RuleOutcome outcome = mx::evaluate(rules, fixedContext());
  require(outcome.fired.size() + outcome.undetermined.size() <= rules.size(), "a rule fires or is undetermined once");
  std::set<std::string> contradicted;
  for (const mx::RuleContradiction& c : outcome.contradictions) contradicted.insert(c.variable);
  for (const auto& [variable, bounds] : outcome.bounds) {
    require(!std::isnan(bounds.lower) && !std::isnan(bounds.upper), "bounds are never NaN");
    require(bounds.empty() == (contradicted.count(variable) != 0),
            "a variable's bounds are empty exactly when a contradiction names it");
  }
  static_cast<void>(mx::staticContradictions(rules));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const mx::RuleParseResult result = mx::parseRuleText(std::string(mx::fuzz::bytesOf(data, size)));
  for (const mx::RuleError& e : result.errors) require(e.line >= 1 && e.column >= 1, "errors name a line and column");
  for (const mx::Rule& rule : result.rules.rules) {
    require(!rule.bound || std::isfinite(rule.bound->value), "a bound is a finite number");
    checkCanonicalText(rule);
  }
  checkOutcome(result.rules);
  return 0;
}
