// The lexer of ISO G-code and of the ISO-based dialects Sinumerik and LinuxCNC (gcode_reader.h).
#include <cmath>
#include <initializer_list>

#include "core/invalid_input.h"
#include "gcode/dialect_lexers.h"
#include "gcode/word_scan.h"

namespace mx::gcode_lex {
namespace {

using namespace gcode_scan;

bool oneOf(double v, std::initializer_list<int> codes) {
  for (const int c : codes)
    if (std::abs(v - c) < 1e-9) return true;
  return false;
}

// G64 is continuous-path mode on Sinumerik and path blending on LinuxCNC: neither changes the path.
bool knownG(double v, GcodeDialect d) {
  if (oneOf(v, {0, 1, 2, 3, 4, 17, 20, 21, 90, 91})) return true;
  if (d == GcodeDialect::Sinumerik) return oneOf(v, {9, 60, 64, 641, 642, 70, 71, 700, 710});
  if (d == GcodeDialect::LinuxCnc) return oneOf(v, {61, 64});
  return false;
}

// The M words every mill controller shares (program stop and end, spindle, tool change, coolant); on
// LinuxCNC also the override controls M48-M53, M52 being the adaptive-feed input.
bool knownM(double v, GcodeDialect d) {
  if (oneOf(v, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 30})) return true;
  if (d == GcodeDialect::Sinumerik) return oneOf(v, {17});
  if (d == GcodeDialect::LinuxCnc) return oneOf(v, {48, 49, 50, 51, 52, 53});
  return false;
}

bool knownLetter(char l) {
  switch (l) {
    case 'F':
    case 'S':
    case 'X':
    case 'Y':
    case 'Z':
    case 'I':
    case 'J':
    case 'P':
    case 'N':
    case 'G':
    case 'M':
      return true;
    default:
      return false;
  }
}

bool isNameChar(char c) {
  return isLetter(c) || isDigit(c) || c == '_';
}

class IsoLexer {
 public:
  IsoLexer(GcodeBlock& block, GcodeDialect dialect, std::vector<GcodeWarning>& warnings)
      : b_(block), s_(block.text), d_(dialect), warnings_(warnings) {}

  void run() {
    lexLineStart();
    while (pos_ < s_.size()) {
      const char c = s_[pos_];
      if (isSpace(c)) {
        ++pos_;
      } else if (c == '(' || c == ';') {
        if (lexComment()) break;
      } else if (c == '#') {
        lexParameter();
      } else if (c == '$' && d_ == GcodeDialect::Sinumerik) {
        lexSystemVariable();
      } else if (isLetter(c)) {
        if (!(d_ == GcodeDialect::Sinumerik && lexSinumerikName())) lexWord();
      } else {
        refuse(pos_, std::max(skipToken(pos_), pos_ + 1) - pos_);
      }
    }
    warnRepeatedWords();
    markEditableWords();
  }

 private:
  GcodeBlock& b_;
  std::string_view s_;
  GcodeDialect d_;
  std::vector<GcodeWarning>& warnings_;
  std::size_t pos_ = 0;
  bool flow_line_ = false;  // a LinuxCNC o-word line: no words of its own to edit or insert

  void warn(std::size_t at, std::size_t len, const std::string& message) {
    warnings_.push_back({b_.line, at + 1, std::string(s_.substr(at, len)), message});
  }
  [[noreturn]] void refuse(std::size_t at, std::size_t len) {
    throw InvalidInput(where(b_.line, at + 1) + excerpt(s_.substr(at, len)) + ": cannot be split into " +
                       std::string(dialectTitle(d_)) + " words (a letter with a number, or a comment)");
  }
  std::size_t skipToken(std::size_t p) const {
    while (p < s_.size() && !isSpace(s_[p]) && s_[p] != '(' && s_[p] != ';') ++p;
    return p;
  }
  void endToken(std::size_t end) {
    pos_ = end;
    b_.words_end = end;
  }
  // From an opening bracket at p, the end just after its match (brackets nest; quoted strings are
  // skipped); npos when it is not closed on the line.
  std::size_t balanced(std::size_t p, char open, char close) const {
    int depth = 0;
    for (; p < s_.size(); ++p) {
      if (s_[p] == '"') {
        const std::size_t q = s_.find('"', p + 1);
        if (q == std::string_view::npos) return std::string_view::npos;
        p = q;
      } else if (s_[p] == open) {
        ++depth;
      } else if (s_[p] == close && --depth == 0) {
        return p + 1;
      }
    }
    return std::string_view::npos;
  }
  // A value after '=' or a parameter reference: a quoted string, or up to a blank, comment or line end
  // outside brackets. An empty value, an unclosed bracket or string cannot be split into words: the
  // program is refused from `word` on.
  std::size_t valueEnd(std::size_t word, std::size_t p) {
    const std::size_t start = p;
    if (p < s_.size() && s_[p] == '"') {
      const std::size_t q = s_.find('"', p + 1);
      if (q == std::string_view::npos) refuse(word, s_.size() - word);
      return q + 1;
    }
    int depth = 0;
    for (; p < s_.size(); ++p) {
      const char c = s_[p];
      if (c == '"') {
        const std::size_t q = s_.find('"', p + 1);
        if (q == std::string_view::npos) refuse(word, s_.size() - word);
        p = q;
        continue;
      }
      if (c == '[' || (c == '(' && d_ == GcodeDialect::Sinumerik)) ++depth;
      if ((c == ']' || (c == ')' && d_ == GcodeDialect::Sinumerik)) && depth > 0) --depth;
      if (depth == 0 && (isSpace(c) || c == ';' || (c == '(' && d_ != GcodeDialect::Sinumerik))) break;
    }
    if (depth > 0 || p == start) refuse(word, std::max(p, start + 1) - word);
    return p;
  }

  // After a name ending at p: the end of its " = value", or p when no '=' follows.
  std::size_t assignedValueEnd(std::size_t p) {
    std::size_t q = p;
    while (q < s_.size() && isSpace(s_[q])) ++q;
    if (q >= s_.size() || s_[q] != '=') return p;
    ++q;
    while (q < s_.size() && isSpace(s_[q])) ++q;
    return valueEnd(pos_, q);
  }

  // Block delete '/', a tape marker '%' (Sinumerik: its "%_N_NAME_MPF" header) and, on LinuxCNC, an
  // o-word line.
  void lexLineStart() {
    std::size_t first = 0;
    while (first < s_.size() && isSpace(s_[first])) ++first;
    if (first < s_.size() && s_[first] == '/') endToken(first + 1);
    if (first < s_.size() && s_[first] == '%')
      endToken(d_ == GcodeDialect::Sinumerik ? std::max(skipToken(first), first + 1) : first + 1);
    if (d_ == GcodeDialect::LinuxCnc && first + 1 < s_.size() && (s_[first] == 'o' || s_[first] == 'O') &&
        (s_[first + 1] == '<' || isDigit(s_[first + 1]))) {
      std::size_t end = first;
      while (end < s_.size() && s_[end] != ';' && s_[end] != '(') ++end;
      while (end > first && isSpace(s_[end - 1])) --end;
      warn(first, end - first, "o-word (subroutine or flow control): kept verbatim, not interpreted");
      endToken(end);
      flow_line_ = true;
    }
  }

  // Returns true when the comment runs to the end of the line.
  bool lexComment() {
    if (s_[pos_] == ';') {
      b_.comments.push_back({pos_ + 1, s_.size() - pos_, std::string(s_.substr(pos_ + 1))});
      pos_ = s_.size();
      return true;
    }
    const std::size_t close = s_.find(')', pos_ + 1);
    const std::size_t end = close == std::string_view::npos ? s_.size() : close + 1;
    if (close == std::string_view::npos) warn(pos_, end - pos_, "unclosed comment: kept to the end of the line");
    const std::size_t inner_end = close == std::string_view::npos ? s_.size() : close;
    b_.comments.push_back({pos_ + 1, end - pos_, std::string(s_.substr(pos_ + 1, inner_end - pos_ - 1))});
    pos_ = end;
    return false;
  }

  // "#<depth> = 2.5", "#100=[#1*2]": a parameter assignment or reference, kept verbatim (evaluated by
  // the controller, not by us).
  void lexParameter() {
    std::size_t p = pos_ + 1;
    if (p < s_.size() && s_[p] == '<') {
      const std::size_t close = s_.find('>', p);
      if (close == std::string_view::npos) refuse(pos_, s_.size() - pos_);
      p = close + 1;
    } else {
      while (p < s_.size() && isDigit(s_[p])) ++p;
      if (p == pos_ + 1) refuse(pos_, std::max(skipToken(pos_), pos_ + 1) - pos_);
    }
    p = assignedValueEnd(p);
    if (d_ != GcodeDialect::LinuxCnc) warn(pos_, p - pos_, "parameter (macro variable): kept verbatim, not evaluated");
    endToken(p);
  }

  void lexSystemVariable() {
    std::size_t p = pos_ + 1;
    while (p < s_.size() && isNameChar(s_[p])) ++p;
    if (p < s_.size() && (s_[p] == '[' || s_[p] == '(')) {  // "$P_UIFR[1]", "$P_UIFRANS(X,10)"
      p = balanced(p, s_[p], s_[p] == '[' ? ']' : ')');
      if (p == std::string_view::npos) refuse(pos_, s_.size() - pos_);
    }
    p = assignedValueEnd(p);
    warn(pos_, p - pos_, "system variable: kept verbatim, not evaluated");
    endToken(p);
  }

  // Sinumerik "NAME=value" and "NAME(args)": returns false when the letters at pos_ are neither (an
  // ordinary word such as "G1X10").
  bool lexSinumerikName() {
    std::size_t p = pos_;
    while (p < s_.size() && isLetter(s_[p])) ++p;
    while (p < s_.size() && isNameChar(s_[p])) ++p;
    const std::string name = upperCopy(s_.substr(pos_, p - pos_));
    std::size_t q = p;
    while (q < s_.size() && (s_[q] == ' ' || s_[q] == '\t')) ++q;
    // A call's name starts with two letters ("CYCLE81", "MSG"): "S1500 (note)" is a word and a comment.
    const bool call_name = name.size() >= 2 && isLetter(name[1]);
    if (q < s_.size() && s_[q] == '(' && call_name) return lexCall(name, q), true;
    if (q < s_.size() && s_[q] == '=' && (q + 1 >= s_.size() || s_[q + 1] != '=')) return lexAssignment(name, q), true;
    return false;
  }

  void lexCall(const std::string& name, std::size_t open) {
    const std::size_t end = balanced(open, '(', ')');
    if (end == std::string_view::npos) refuse(pos_, s_.size() - pos_);
    GcodeWord w;
    w.letter = name[0];
    w.address = name;
    w.column = pos_ + 1;
    w.length = end - pos_;
    w.has_value = false;
    w.known = name.rfind("CYCLE", 0) == 0 || name == "MSG";
    if (!w.known) warn(pos_, w.length, "call: kept verbatim, not interpreted");
    b_.words.push_back(std::move(w));
    endToken(end);
  }

  // S1=2000 (the first spindle's speed), S=, F=, CR= (arc radius) are words; other assignments and
  // expressions are kept verbatim and warned about.
  void lexAssignment(const std::string& name, std::size_t equals) {
    std::size_t v = equals + 1;
    while (v < s_.size() && (s_[v] == ' ' || s_[v] == '\t')) ++v;
    const std::size_t end = valueEnd(pos_, v);
    GcodeWord w;
    w.letter = name[0];
    w.address = name;
    w.column = pos_ + 1;
    w.length = end - pos_;
    w.value_at = v - pos_;
    double value = 0.0;
    const bool numeric = end > v && scanNumber(s_, v, value) == end;
    w.has_value = numeric;
    w.value = numeric ? value : 0.0;
    const bool word = name == "S" || name == "S1" || name == "F" || name == "CR";
    w.known = numeric && word;
    if (w.known) {
      if (name == "S1") w.address = "S";
      checkWordRange(b_, w);
    } else {
      warn(pos_, w.length,
           numeric ? "assignment: kept verbatim" : "value is an expression: kept verbatim, not evaluated");
    }
    b_.words.push_back(std::move(w));
    endToken(end);
  }

  void lexWord() {
    const char c = s_[pos_];
    std::size_t p = pos_ + 1;
    while (p < s_.size() && (s_[p] == ' ' || s_[p] == '\t')) ++p;
    if (p < s_.size() && (s_[p] == '[' || s_[p] == '#') && d_ != GcodeDialect::Sinumerik) return lexExpressionWord(p);
    double value = 0.0;
    const std::size_t end = scanNumber(s_, p, value);
    if (end == p) {  // a letter without a number: an unknown word
      const std::size_t tend = skipToken(pos_ + 1);
      if (knownLetter(upper(c)) && namesNonFinite(s_.substr(p, tend - p)))
        throw InvalidInput(where(b_.line, pos_ + 1) + excerpt(s_.substr(pos_, tend - pos_)) +
                           ": a word's value must be a finite number");
      warn(pos_, tend - pos_, "word without a number: kept verbatim");
      return endToken(tend);
    }
    GcodeWord w;
    w.letter = upper(c);
    w.address = std::string(1, w.letter);
    w.value = value;
    w.column = pos_ + 1;
    w.length = end - pos_;
    w.value_at = p - pos_;
    w.known = knownLetter(w.letter) && (w.letter != 'G' || knownG(value, d_)) && (w.letter != 'M' || knownM(value, d_));
    if (!w.known) warn(pos_, w.length, "unknown word: kept verbatim");
    if (w.known) checkWordRange(b_, w);
    b_.words.push_back(std::move(w));
    endToken(end);
  }

  // "X[#1*2]", "X#<x>": a word whose value the controller computes.
  void lexExpressionWord(std::size_t value_start) {
    std::size_t end = 0;
    if (s_[value_start] == '[') {
      end = balanced(value_start, '[', ']');
      if (end == std::string_view::npos) refuse(pos_, s_.size() - pos_);
    } else {
      end = valueEnd(pos_, value_start);
    }
    GcodeWord w;
    w.letter = upper(s_[pos_]);
    w.address = std::string(1, w.letter);
    w.column = pos_ + 1;
    w.length = end - pos_;
    w.value_at = value_start - pos_;
    w.has_value = false;
    warn(pos_, w.length, "value is an expression: kept verbatim, not evaluated");
    b_.words.push_back(std::move(w));
    endToken(end);
  }

  // Repeated words of the same known letter (except G and M, of which a block may hold several) are
  // ambiguous: the first one is used.
  void warnRepeatedWords() {
    for (std::size_t i = 0; i < b_.words.size(); ++i) {
      const auto& w = b_.words[i];
      if (!w.known || !w.has_value || w.letter == 'G' || w.letter == 'M') continue;
      for (std::size_t j = 0; j < i; ++j)
        if (b_.words[j].known && b_.words[j].address == w.address) {
          warn(w.column - 1, w.length, "repeated word: the first one is used");
          break;
        }
    }
  }

  void markEditableWords() {
    // Sinumerik's G4 F.. / S.. are a dwell in seconds / revolutions, and an o-word line is flow control:
    // no feed or speed to edit or add.
    if ((d_ == GcodeDialect::Sinumerik && b_.hasG(4)) || flow_line_) {
      b_.feed_insert_at = b_.speed_insert_at = std::string::npos;
      return;
    }
    for (std::size_t i = 0; i < b_.words.size(); ++i) {
      const auto& w = b_.words[i];
      if (!w.known || !w.has_value) continue;
      if (w.address == "F" && b_.feed_word < 0) b_.feed_word = static_cast<int>(i);
      if (w.address == "S" && b_.speed_word < 0) b_.speed_word = static_cast<int>(i);
    }
    b_.feed_insert_at = b_.words_end;
    b_.speed_insert_at = b_.words_end;
  }
};

}  // namespace

void lexIsoFamilyLine(GcodeBlock& block, GcodeDialect dialect, std::vector<GcodeWarning>& warnings) {
  IsoLexer(block, dialect, warnings).run();
}

}  // namespace mx::gcode_lex
