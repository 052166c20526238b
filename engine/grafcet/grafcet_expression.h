#pragma once
// Receptivities of Grafcet transitions: a small Boolean language over named signals.
//   or-expr    := and-expr { ("or" | "||") and-expr }
//   and-expr   := not-expr { ("and" | "&&") not-expr }
//   not-expr   := ("not" | "!") not-expr | comparison
//   comparison := postfix [ ("<" | "<=" | ">" | ">=" | "==" | "=" | "!=") postfix ]   (not chained)
//   postfix    := primary { "'" }          the paper's complement: a' = not a
//   primary    := signal | number | "true" | "false" | "-" primary | "(" or-expr ")"
// Signals are identifiers [A-Za-z_][A-Za-z0-9_]*; keywords are case-insensitive. Values are doubles:
// a Boolean signal is 0 or 1, any nonzero (non-NaN) value is true, comparisons and logic give 0/1.
// Expressions compile once into postfix code whose signal operands are indices, so evaluation does
// no string work (the interpreter's fast path binds them to a value vector).
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "supervisor/supervisor_logic.h"

namespace mx {

// A syntax error: what() is "line L, column C: <reason>" (1-based, columns count characters).
class GrafcetParseError : public std::runtime_error {
 public:
  GrafcetParseError(int line, int column, const std::string& reason);
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& reason() const { return reason_; }

 private:
  int line_;
  int column_;
  std::string reason_;
};

class GrafcetExpression {
 public:
  GrafcetExpression();  // the constant "false"
  // Throws GrafcetParseError.
  static GrafcetExpression parse(std::string_view text);

  const std::string& text() const { return text_; }
  // The signals the expression reads, each once, in order of first appearance.
  const std::vector<std::string>& signalNames() const { return signals_; }
  bool isConstant() const { return signals_.empty(); }

  // Evaluation by name; a signal absent from `values` reads 0 (false).
  double value(const SignalValues& values) const;
  bool evaluate(const SignalValues& values) const;

  // Fast path: signalNames()[i] reads cells[slotOf[i]], where slotOf is set by bindSlots (identity by
  // default, i.e. cells[i] is the value of signalNames()[i]).
  void bindSlots(std::vector<int> slotOf);
  double value(const double* cells) const;
  bool evaluate(const double* cells) const;

  static bool truth(double v) { return v > 0.0 || v < 0.0; }  // nonzero, NaN is false

 private:
  enum class Op : std::uint8_t { Const, Signal, Not, Neg, And, Or, Lt, Le, Gt, Ge, Eq, Ne };
  struct Instr {
    Op op;
    int index;     // Signal: index in signals_
    double value;  // Const
  };
  template <class Fetch>
  double run(Fetch fetch) const;

  friend class GrafcetExpressionParser;
  std::string text_;
  std::vector<Instr> code_;
  std::vector<std::string> signals_;
  std::vector<int> slot_of_;
  int max_stack_ = 1;
};

}  // namespace mx
