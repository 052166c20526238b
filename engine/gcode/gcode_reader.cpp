#include "gcode/gcode_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "core/invalid_input.h"

namespace mx {
namespace {

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
bool isLetter(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
char upper(char c) {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

bool knownG(double v) {
  static constexpr int kG[] = {0, 1, 2, 3, 4, 17, 20, 21, 90, 91};
  for (int g : kG)
    if (std::abs(v - g) < 1e-9) return true;
  return false;
}

// The M words every mill controller shares (program stop and end, spindle, tool change, coolant). They
// are kept verbatim like any word; knowing them spares a warning on nearly every program.
bool knownM(double v) {
  static constexpr int kM[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 30};
  for (int m : kM)
    if (std::abs(v - m) < 1e-9) return true;
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

// Scans [sign] digits [. digits] from pos; returns the end (== pos when no number).
std::size_t scanNumber(std::string_view s, std::size_t pos, double& value) {
  std::size_t p = pos;
  bool negative = false;
  if (p < s.size() && (s[p] == '+' || s[p] == '-')) {
    negative = s[p] == '-';
    ++p;
  }
  const std::size_t digits_start = p;
  std::size_t ndigits = 0;
  while (p < s.size() && isDigit(s[p])) ++p, ++ndigits;
  if (p < s.size() && s[p] == '.') {
    ++p;
    while (p < s.size() && isDigit(s[p])) ++p, ++ndigits;
  }
  if (ndigits == 0) return pos;
  std::string_view num = s.substr(digits_start, p - digits_start);
  std::string buf;
  if (num.front() == '.') {  // from_chars needs a leading digit
    buf = "0";
    buf += num;
    num = buf;
  }
  double v = 0.0;
  auto res = std::from_chars(num.data(), num.data() + num.size(), v, std::chars_format::fixed);
  if (res.ec != std::errc()) return pos;
  value = negative ? -v : v;
  return p;
}

// "nan", "inf", "infinity" in any case, with an optional sign: what a writer of non-finite numbers emits.
bool namesNonFinite(std::string_view token) {
  if (!token.empty() && (token.front() == '+' || token.front() == '-')) token.remove_prefix(1);
  std::string lower;
  for (const char c : token.substr(0, 3)) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return lower == "nan" || lower == "inf";
}

std::string shortNumber(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// Throws InvalidInput when a known word's value is outside its letter's range.
void checkWordRange(const GcodeBlock& b, const GcodeWord& w) {
  double lo = 0.0, hi = 0.0;
  const char* what = "";
  switch (w.letter) {
    case 'S':
      hi = GcodeWordLimits::kMaxSpindleRpm, what = " rpm (spindle speed)";
      break;
    case 'F':
      hi = GcodeWordLimits::kMaxFeed, what = " per minute (feed)";
      break;
    case 'P':
      hi = GcodeWordLimits::kMaxDwellS, what = " s (dwell)";
      break;
    case 'X':
    case 'Y':
    case 'Z':
    case 'I':
    case 'J':
      lo = -GcodeWordLimits::kMaxCoordinate, hi = GcodeWordLimits::kMaxCoordinate, what = " (coordinate)";
      break;
    default:
      return;
  }
  if (w.value >= lo && w.value <= hi) return;
  throw InvalidInput("line " + std::to_string(b.line) + ", column " + std::to_string(w.column) + ": " +
                     b.text.substr(w.column - 1, std::min<std::size_t>(w.length, 40)) + " = " + shortNumber(w.value) +
                     ": must be in [" + shortNumber(lo) + ", " + shortNumber(hi) + "]" + what);
}

}  // namespace

void GcodeReader::lexLine(GcodeBlock& b, std::vector<GcodeWarning>& warnings) {
  const std::string_view s = b.text;
  std::size_t pos = 0;
  auto warn = [&](std::size_t col, std::size_t len, const std::string& msg) {
    warnings.push_back({b.line, col + 1, std::string(s.substr(col, len)), msg});
  };
  // A tape marker line ("%", possibly with spaces or a comment after it) is part of the subset.
  std::size_t first = 0;
  while (first < s.size() && isSpace(s[first])) ++first;
  if (first < s.size() && s[first] == '%') pos = first + 1, b.words_end = pos;

  auto skipToken = [&](std::size_t p) {
    while (p < s.size() && !isSpace(s[p]) && s[p] != '(' && s[p] != ';') ++p;
    return p;
  };
  while (pos < s.size()) {
    const char c = s[pos];
    if (isSpace(c)) {
      ++pos;
      continue;
    }
    if (c == '(') {
      std::size_t close = s.find(')', pos + 1);
      std::size_t end = close == std::string_view::npos ? s.size() : close + 1;
      if (close == std::string_view::npos) warn(pos, end - pos, "unclosed comment: kept to the end of the line");
      const std::size_t inner_end = close == std::string_view::npos ? s.size() : close;
      b.comments.push_back({pos + 1, end - pos, std::string(s.substr(pos + 1, inner_end - pos - 1))});
      pos = end;
      continue;
    }
    if (c == ';') {
      b.comments.push_back({pos + 1, s.size() - pos, std::string(s.substr(pos + 1))});
      break;
    }
    if (isLetter(c)) {
      std::size_t p = pos + 1;
      while (p < s.size() && (s[p] == ' ' || s[p] == '\t')) ++p;
      double value = 0.0;
      const std::size_t end = scanNumber(s, p, value);
      if (end == p) {  // a letter without a number: unknown token
        const std::size_t tend = skipToken(pos + 1);
        if (knownLetter(upper(c)) && namesNonFinite(s.substr(p, tend - p)))
          throw InvalidInput("line " + std::to_string(b.line) + ", column " + std::to_string(pos + 1) + ": " +
                             std::string(s.substr(pos, std::min<std::size_t>(tend - pos, 40))) +
                             ": a word's value must be a finite number");
        warn(pos, tend - pos, "word without a number: kept verbatim");
        pos = tend;
        b.words_end = pos;
        continue;
      }
      GcodeWord w;
      w.letter = upper(c);
      w.value = value;
      w.column = pos + 1;
      w.length = end - pos;
      w.known = knownLetter(w.letter) && (w.letter != 'G' || knownG(value)) && (w.letter != 'M' || knownM(value));
      if (!w.known) warn(pos, w.length, "unknown word: kept verbatim");
      if (w.known) checkWordRange(b, w);
      b.words.push_back(w);
      pos = end;
      b.words_end = pos;
      continue;
    }
    const std::size_t tend = std::max(skipToken(pos), pos + 1);
    warn(pos, tend - pos, "unrecognised text: kept verbatim");
    pos = tend;
    b.words_end = pos;
  }
  // Repeated words of the same known letter (except G and M, of which a block may hold several) are
  // ambiguous: the first one is used.
  for (std::size_t i = 0; i < b.words.size(); ++i) {
    const auto& w = b.words[i];
    if (!w.known || w.letter == 'G' || w.letter == 'M') continue;
    for (std::size_t j = 0; j < i; ++j)
      if (b.words[j].letter == w.letter) {
        warn(w.column - 1, w.length, "repeated word: the first one is used");
        break;
      }
  }
}

GcodeProgram GcodeReader::parse(std::string_view text) {
  GcodeProgram prog;
  prog.blocks.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1);
  std::size_t start = 0;
  int line = 0;
  while (start < text.size()) {
    std::size_t nl = text.find('\n', start);
    GcodeBlock b;
    b.line = ++line;
    if (nl == std::string_view::npos) {
      b.text = std::string(text.substr(start));
      b.eol.clear();
      start = text.size();
    } else {
      std::size_t end = nl;
      if (end > start && text[end - 1] == '\r') {
        --end;
        b.eol = "\r\n";
      } else {
        b.eol = "\n";
      }
      b.text = std::string(text.substr(start, end - start));
      start = nl + 1;
    }
    if (b.text.size() > kMaxGcodeLineLength)
      throw InvalidInput("line " + std::to_string(b.line) + ": " + std::to_string(b.text.size()) +
                         " characters: a block has at most " + std::to_string(kMaxGcodeLineLength));
    lexLine(b, prog.warnings);
    if (b.eol.empty())
      prog.warnings.push_back({b.line, 0, b.text, "last line has no line end (truncated?): kept as is"});
    prog.blocks.push_back(std::move(b));
  }
  return prog;
}

GcodeProgram GcodeReader::readFile(const std::string& path) {
  std::string text;
  try {
    text = readInputFile(path, kPartProgramFileLimit);
  } catch (const InvalidInput& e) {
    throw InvalidInput("gcode file = " + path + ": " + e.what());
  }
  return parse(text);
}

}  // namespace mx
