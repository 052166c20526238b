#include "gcode/word_scan.h"

#include <algorithm>
#include <charconv>
#include <sstream>

#include "core/invalid_input.h"
#include "gcode/gcode_reader.h"

namespace mx::gcode_scan {

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

bool namesNonFinite(std::string_view token) {
  if (!token.empty() && (token.front() == '+' || token.front() == '-')) token.remove_prefix(1);
  std::string lower;
  for (const char c : token.substr(0, 3)) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return lower == "nan" || lower == "inf";
}

namespace {

std::string shortNumber(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace

std::string where(int line, std::size_t column) {
  return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": ";
}

std::string excerpt(std::string_view text) {
  return std::string(text.substr(0, 40));
}

void checkWordRange(const GcodeBlock& b, const GcodeWord& w) {
  if (!w.has_value) return;
  double lo = 0.0, hi = 0.0;
  const char* what = "";
  // Sinumerik's arc radius CR= is a length like R.
  switch (w.address == "CR" ? 'R' : w.letter) {
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
    case 'R':
      lo = -GcodeWordLimits::kMaxCoordinate, hi = GcodeWordLimits::kMaxCoordinate, what = " (coordinate)";
      break;
    default:
      return;
  }
  if (w.value >= lo && w.value <= hi) return;
  throw InvalidInput(where(b.line, w.column) + excerpt(std::string_view(b.text).substr(w.column - 1, w.length)) +
                     " = " + shortNumber(w.value) + ": must be in [" + shortNumber(lo) + ", " + shortNumber(hi) + "]" +
                     what);
}

}  // namespace mx::gcode_scan
