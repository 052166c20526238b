#include "grafcet/grafcet_expression.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace mx {

namespace {

std::string positionText(int line, int column, const std::string& reason) {
  return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + reason;
}

enum class Tok { End, Ident, Number, True, False, LParen, RParen, Not, And, Or, Prime, Minus, Lt, Le, Gt, Ge, Eq, Ne };

struct Token {
  Tok kind = Tok::End;
  std::string text;  // as written
  double number = 0.0;
  int line = 1;
  int column = 1;
};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool identStart(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool identChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

class Lexer {
 public:
  explicit Lexer(std::string_view text) : s_(text) {}

  std::vector<Token> run() {
    std::vector<Token> out;
    for (;;) {
      skipSpace();
      Token t;
      t.line = line_;
      t.column = column_;
      if (i_ >= s_.size()) {
        out.push_back(t);
        return out;
      }
      const char c = s_[i_];
      const std::size_t start = i_;
      if (identStart(c)) {
        while (i_ < s_.size() && identChar(s_[i_])) advance();
        t.text = std::string(s_.substr(start, i_ - start));
        const std::string k = lower(t.text);
        t.kind = k == "and"     ? Tok::And
                 : k == "or"    ? Tok::Or
                 : k == "not"   ? Tok::Not
                 : k == "true"  ? Tok::True
                 : k == "false" ? Tok::False
                                : Tok::Ident;
      } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                 (c == '.' && i_ + 1 < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_ + 1])))) {
        number(t);
      } else if (c == '\'') {
        advance();
        t.kind = Tok::Prime;
      } else if (static_cast<unsigned char>(c) == 0xE2 && i_ + 2 < s_.size() &&
                 static_cast<unsigned char>(s_[i_ + 1]) == 0x80 &&
                 (static_cast<unsigned char>(s_[i_ + 2]) == 0x98 || static_cast<unsigned char>(s_[i_ + 2]) == 0x99)) {
        advance(3);  // typographic quotes U+2018 / U+2019, as the paper prints the complement
        t.kind = Tok::Prime;
      } else {
        auto two = [&](char a, char b) { return c == a && i_ + 1 < s_.size() && s_[i_ + 1] == b; };
        if (two('&', '&')) {
          advance(2);
          t.kind = Tok::And;
        } else if (two('|', '|')) {
          advance(2);
          t.kind = Tok::Or;
        } else if (two('<', '=')) {
          advance(2);
          t.kind = Tok::Le;
        } else if (two('>', '=')) {
          advance(2);
          t.kind = Tok::Ge;
        } else if (two('=', '=')) {
          advance(2);
          t.kind = Tok::Eq;
        } else if (two('!', '=')) {
          advance(2);
          t.kind = Tok::Ne;
        } else if (c == '<') {
          advance();
          t.kind = Tok::Lt;
        } else if (c == '>') {
          advance();
          t.kind = Tok::Gt;
        } else if (c == '=') {
          advance();
          t.kind = Tok::Eq;
        } else if (c == '!') {
          advance();
          t.kind = Tok::Not;
        } else if (c == '(') {
          advance();
          t.kind = Tok::LParen;
        } else if (c == ')') {
          advance();
          t.kind = Tok::RParen;
        } else if (c == '-') {
          advance();
          t.kind = Tok::Minus;
        } else {
          std::string shown(1, c);
          if (static_cast<unsigned char>(c) >= 0x80 || !std::isprint(static_cast<unsigned char>(c))) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned>(static_cast<unsigned char>(c)));
            shown = buf;
          }
          throw GrafcetParseError(t.line, t.column, "unexpected character '" + shown + "'");
        }
      }
      if (t.text.empty()) t.text = std::string(s_.substr(start, i_ - start));
      out.push_back(std::move(t));
    }
  }

 private:
  void advance(std::size_t n = 1) {
    for (std::size_t k = 0; k < n && i_ < s_.size(); ++k) {
      const unsigned char c = static_cast<unsigned char>(s_[i_++]);
      if (c == '\n') {
        ++line_;
        column_ = 1;
      } else if ((c & 0xC0) != 0x80) {
        ++column_;  // a character, not a UTF-8 continuation byte
      }
    }
  }
  void skipSpace() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) advance();
  }
  void number(Token& t) {
    const std::size_t start = i_;
    while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) advance();
    if (i_ < s_.size() && s_[i_] == '.') {
      advance();
      while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) advance();
    }
    if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      std::size_t j = i_ + 1;
      if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
      if (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) {
        advance(j - i_);
        while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) advance();
      }
    }
    if (i_ < s_.size() && identChar(s_[i_]))
      throw GrafcetParseError(line_, column_, "unexpected '" + std::string(1, s_[i_]) + "' in a number");
    const std::string_view digits = s_.substr(start, i_ - start);
    double v = 0.0;
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (r.ec != std::errc() || !std::isfinite(v))
      throw GrafcetParseError(t.line, t.column, "invalid number '" + std::string(digits) + "'");
    t.kind = Tok::Number;
    t.number = v;
  }

  std::string_view s_;
  std::size_t i_ = 0;
  int line_ = 1;
  int column_ = 1;
};

const char* describe(Tok k) {
  switch (k) {
    case Tok::End:
      return "the end of the expression";
    case Tok::RParen:
      return "')'";
    case Tok::LParen:
      return "'('";
    default:
      return nullptr;
  }
}

std::string found(const Token& t) {
  if (const char* d = describe(t.kind)) return d;
  return "'" + t.text + "'";
}

}  // namespace

GrafcetParseError::GrafcetParseError(int line, int column, const std::string& reason)
    : std::runtime_error(positionText(line, column, reason)), line_(line), column_(column), reason_(reason) {}

// Recursive descent emitting postfix code.
class GrafcetExpressionParser {
 public:
  using Op = GrafcetExpression::Op;
  GrafcetExpressionParser(std::vector<Token> tokens, GrafcetExpression& out) : t_(std::move(tokens)), out_(out) {}

  void run() {
    if (t_.front().kind == Tok::End) fail(t_.front(), "empty receptivity");
    orExpr();
    if (peek().kind != Tok::End) {
      const Token& t = peek();
      fail(t, t.kind == Tok::RParen ? "unmatched ')'" : "expected an operator, found " + found(t));
    }
  }

 private:
  static constexpr int kMaxDepth = 200;

  const Token& peek() const { return t_[p_]; }
  const Token& next() { return t_[p_ < t_.size() - 1 ? p_++ : p_]; }
  [[noreturn]] static void fail(const Token& at, const std::string& reason) {
    throw GrafcetParseError(at.line, at.column, reason);
  }
  void emit(Op op, int index = 0, double value = 0.0) {
    out_.code_.push_back({op, index, value});
    switch (op) {
      case Op::Const:
      case Op::Signal:
        ++depth_;
        break;
      case Op::Not:
      case Op::Neg:
        break;
      default:
        --depth_;
        break;
    }
    out_.max_stack_ = std::max(out_.max_stack_, depth_);
  }
  struct Nest {
    explicit Nest(GrafcetExpressionParser& p) : p_(p) {
      if (++p_.nesting_ > kMaxDepth) fail(p_.peek(), "expression nested too deeply");
    }
    ~Nest() { --p_.nesting_; }
    GrafcetExpressionParser& p_;
  };

  void orExpr() {
    Nest n(*this);
    andExpr();
    while (peek().kind == Tok::Or) {
      next();
      andExpr();
      emit(Op::Or);
    }
  }
  void andExpr() {
    notExpr();
    while (peek().kind == Tok::And) {
      next();
      notExpr();
      emit(Op::And);
    }
  }
  void notExpr() {
    if (peek().kind == Tok::Not) {
      Nest n(*this);
      next();
      notExpr();
      emit(Op::Not);
      return;
    }
    comparison();
  }
  static bool isComparison(Tok k) {
    return k == Tok::Lt || k == Tok::Le || k == Tok::Gt || k == Tok::Ge || k == Tok::Eq || k == Tok::Ne;
  }
  void comparison() {
    postfix();
    if (!isComparison(peek().kind)) return;
    const Tok k = next().kind;
    postfix();
    emit(k == Tok::Lt   ? Op::Lt
         : k == Tok::Le ? Op::Le
         : k == Tok::Gt ? Op::Gt
         : k == Tok::Ge ? Op::Ge
         : k == Tok::Eq ? Op::Eq
                        : Op::Ne);
    if (isComparison(peek().kind)) fail(peek(), "comparisons cannot be chained; use 'and'");
  }
  void postfix() {
    primary();
    while (peek().kind == Tok::Prime) {
      next();
      emit(Op::Not);
    }
  }
  void primary() {
    const Token& t = peek();
    switch (t.kind) {
      case Tok::Ident: {
        next();
        auto& sig = out_.signals_;
        auto it = std::find(sig.begin(), sig.end(), t.text);
        const int index = static_cast<int>(it - sig.begin());
        if (it == sig.end()) sig.push_back(t.text);
        emit(Op::Signal, index);
        return;
      }
      case Tok::Number:
        next();
        emit(Op::Const, 0, t.number);
        return;
      case Tok::True:
        next();
        emit(Op::Const, 0, 1.0);
        return;
      case Tok::False:
        next();
        emit(Op::Const, 0, 0.0);
        return;
      case Tok::Minus: {
        Nest n(*this);
        next();
        primary();
        emit(Op::Neg);
        return;
      }
      case Tok::LParen: {
        next();
        orExpr();
        if (peek().kind != Tok::RParen) fail(peek(), "expected ')'");
        next();
        return;
      }
      default:
        fail(t, "expected a signal, a number or '(', found " + found(t));
    }
  }

  std::vector<Token> t_;
  std::size_t p_ = 0;
  GrafcetExpression& out_;
  int depth_ = 0;
  int nesting_ = 0;
};

GrafcetExpression::GrafcetExpression() : text_("false"), code_{{Op::Const, 0, 0.0}} {}

GrafcetExpression GrafcetExpression::parse(std::string_view text) {
  GrafcetExpression e;
  e.text_ = std::string(text);
  e.code_.clear();
  e.max_stack_ = 1;
  GrafcetExpressionParser(Lexer(text).run(), e).run();
  e.slot_of_.resize(e.signals_.size());
  for (std::size_t i = 0; i < e.slot_of_.size(); ++i) e.slot_of_[i] = static_cast<int>(i);
  return e;
}

void GrafcetExpression::bindSlots(std::vector<int> slotOf) {
  if (slotOf.size() != signals_.size())
    throw std::invalid_argument("GrafcetExpression::bindSlots: one slot per signal expected");
  slot_of_ = std::move(slotOf);
}

template <class Fetch>
double GrafcetExpression::run(Fetch fetch) const {
  double small[16] = {};
  std::vector<double> big;
  double* st = small;
  if (max_stack_ > 16) {
    big.resize(static_cast<std::size_t>(max_stack_));
    st = big.data();
  }
  int sp = -1;
  for (const Instr& in : code_) {
    switch (in.op) {
      case Op::Const:
        st[++sp] = in.value;
        break;
      case Op::Signal:
        st[++sp] = fetch(in.index);
        break;
      case Op::Not:
        st[sp] = truth(st[sp]) ? 0.0 : 1.0;
        break;
      case Op::Neg:
        st[sp] = -st[sp];
        break;
      case Op::And:
        --sp;
        st[sp] = (truth(st[sp]) && truth(st[sp + 1])) ? 1.0 : 0.0;
        break;
      case Op::Or:
        --sp;
        st[sp] = (truth(st[sp]) || truth(st[sp + 1])) ? 1.0 : 0.0;
        break;
      case Op::Lt:
        --sp;
        st[sp] = st[sp] < st[sp + 1] ? 1.0 : 0.0;
        break;
      case Op::Le:
        --sp;
        st[sp] = st[sp] <= st[sp + 1] ? 1.0 : 0.0;
        break;
      case Op::Gt:
        --sp;
        st[sp] = st[sp] > st[sp + 1] ? 1.0 : 0.0;
        break;
      case Op::Ge:
        --sp;
        st[sp] = st[sp] >= st[sp + 1] ? 1.0 : 0.0;
        break;
      case Op::Eq:
        --sp;
        st[sp] = st[sp] == st[sp + 1] ? 1.0 : 0.0;
        break;
      case Op::Ne:
        --sp;
        st[sp] = st[sp] != st[sp + 1] ? 1.0 : 0.0;
        break;
    }
  }
  return st[0];
}

double GrafcetExpression::value(const SignalValues& values) const {
  return run([&](int i) {
    const auto it = values.find(signals_[static_cast<std::size_t>(i)]);
    return it == values.end() ? 0.0 : it->second;
  });
}

bool GrafcetExpression::evaluate(const SignalValues& values) const {
  return truth(value(values));
}

double GrafcetExpression::value(const double* cells) const {
  return run([&](int i) { return cells[slot_of_[static_cast<std::size_t>(i)]]; });
}

bool GrafcetExpression::evaluate(const double* cells) const {
  return truth(value(cells));
}

}  // namespace mx
