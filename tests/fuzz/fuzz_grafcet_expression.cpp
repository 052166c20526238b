// Fuzz target of the Grafcet receptivity language (engine/grafcet/grafcet_expression.h): any text is
// a GrafcetParseError with its line and column, or an expression that keeps its promises: it keeps
// its text, names each signal it reads once, and evaluates the same by name and on the fast path
// (bound slots), with truth() of the value as its Boolean result.
#include <bit>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "fuzz_check.h"
#include "grafcet/grafcet_expression.h"

namespace {

using mx::fuzz::require;

bool sameValue(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Signal values from the input: Boolean levels mostly, and a few analog and edge values.
double signalValue(mx::fuzz::InputNumbers& numbers) {
  static const double kEdges[] = {0.0, 1.0, -1.0, 0.5, -0.0, 1e308, -1e308, 5e-324};
  const std::uint64_t pick = numbers.next();
  return pick % 4 == 0 ? numbers.uniform(-1e3, 1e3) : kEdges[(pick >> 8) % std::size(kEdges)];
}

void checkEvaluation(mx::GrafcetExpression& expression, mx::fuzz::InputNumbers& numbers) {
  const std::vector<std::string>& names = expression.signalNames();
  require(std::set<std::string>(names.begin(), names.end()).size() == names.size(), "each signal is named once");
  // The slots run backwards over the cells, so that a mix-up between names and slots shows.
  std::vector<int> slots(names.size());
  for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(slots.size() - 1 - i);
  expression.bindSlots(slots);
  for (int round = 0; round < 4; ++round) {
    mx::SignalValues byName;
    std::vector<double> cells(names.size() + 1);
    for (std::size_t i = 0; i < names.size(); ++i) {
      byName[names[i]] = signalValue(numbers);
      cells[static_cast<std::size_t>(slots[i])] = byName[names[i]];
    }
    const double value = expression.value(byName);
    require(sameValue(value, expression.value(cells.data())), "evaluation by name and by slot agree");
    require(expression.evaluate(byName) == mx::GrafcetExpression::truth(value), "evaluate is truth of the value");
    require(expression.evaluate(cells.data()) == expression.evaluate(byName), "both paths give the same truth");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = mx::fuzz::bytesOf(data, size);
  mx::GrafcetExpression expression;
  try {
    expression = mx::GrafcetExpression::parse(text);
  } catch (const mx::GrafcetParseError& e) {
    require(e.line() >= 1 && e.column() >= 1, "a syntax error names its line and column");
    return 0;
  }
  require(expression.text() == text, "the expression keeps its text");
  require(expression.isConstant() == expression.signalNames().empty(), "constant exactly without signals");
  mx::fuzz::InputNumbers numbers(text);
  checkEvaluation(expression, numbers);
  return 0;
}
