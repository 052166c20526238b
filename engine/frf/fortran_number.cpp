#include "frf/fortran_number.h"

#include <charconv>
#include <cmath>

namespace mx {
namespace {

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
bool isBlank(char c) {
  return c == ' ' || c == '\t';
}
bool isSign(char c) {
  return c == '+' || c == '-';
}

// End of the number's characters from pos, or pos when the grammar is not met.
std::size_t numberEnd(std::string_view s, std::size_t pos) {
  std::size_t p = pos;
  if (p < s.size() && isSign(s[p])) ++p;
  std::size_t digits = 0;
  while (p < s.size() && isDigit(s[p])) ++p, ++digits;
  if (p < s.size() && s[p] == '.') {
    ++p;
    while (p < s.size() && isDigit(s[p])) ++p, ++digits;
  }
  if (digits == 0) return pos;
  if (p < s.size() && (s[p] == 'E' || s[p] == 'e' || s[p] == 'D' || s[p] == 'd')) {
    ++p;
    if (p < s.size() && isSign(s[p])) ++p;
    std::size_t exp_digits = 0;
    while (p < s.size() && isDigit(s[p])) ++p, ++exp_digits;
    if (exp_digits == 0) return pos;
  }
  if (p < s.size() && !isBlank(s[p]) && !isSign(s[p])) return pos;
  return p;
}

}  // namespace

bool scanFortranNumber(std::string_view text, std::size_t& pos, double& value) {
  const std::size_t end = numberEnd(text, pos);
  if (end == pos) return false;
  // from_chars takes no '+', no leading '.', no 'D' exponent: rewrite into a small buffer.
  char buf[80];
  std::size_t n = 0;
  std::size_t p = pos;
  bool negative = false;
  if (isSign(text[p])) negative = text[p++] == '-';
  if (end - p + 2 > sizeof(buf)) return false;
  if (text[p] == '.') buf[n++] = '0';
  for (; p < end; ++p) {
    const char c = text[p];
    buf[n++] = (c == 'D' || c == 'd') ? 'E' : c;
  }
  double v = 0.0;
  const auto res = std::from_chars(buf, buf + n, v, std::chars_format::general);
  if (res.ec != std::errc() || res.ptr != buf + n || !std::isfinite(v)) return false;
  value = negative ? -v : v;
  pos = end;
  return true;
}

bool parseFortranNumber(std::string_view text, double& value) {
  std::size_t pos = skipBlanks(text, 0);
  double v = 0.0;
  if (!scanFortranNumber(text, pos, v)) return false;
  if (skipBlanks(text, pos) != text.size()) return false;
  value = v;
  return true;
}

std::size_t skipBlanks(std::string_view text, std::size_t pos) {
  while (pos < text.size() && isBlank(text[pos])) ++pos;
  return pos;
}

std::string_view tokenAt(std::string_view text, std::size_t pos) {
  std::size_t end = pos;
  while (end < text.size() && !isBlank(text[end])) ++end;
  return text.substr(pos, end - pos);
}

}  // namespace mx
