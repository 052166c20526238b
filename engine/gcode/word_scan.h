#pragma once
// Character classes, case folding and number scanning shared by the dialect lexers (iso_lexer.cpp,
// heidenhain_lexer.cpp) and the dialect detection, and the range check of known words.
#include <cstddef>
#include <string>
#include <string_view>

#include "gcode/gcode_block.h"

namespace mx::gcode_scan {

inline bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
inline bool isLetter(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
inline bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
inline char upper(char c) {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}
// The text with its ASCII letters upper-cased (words and keywords are case-blind in every dialect).
inline std::string upperCopy(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = upper(c);
  return out;
}

// Scans [sign] digits [. digits] from pos; returns the end (== pos when no number).
std::size_t scanNumber(std::string_view s, std::size_t pos, double& value);
// "nan", "inf", "infinity" in any case, with an optional sign: what a writer of non-finite numbers emits.
bool namesNonFinite(std::string_view token);
// Throws InvalidInput when a known F, S, P or coordinate word's value is outside GcodeWordLimits.
void checkWordRange(const GcodeBlock& block, const GcodeWord& word);
// "line 3, column 7: " for messages.
std::string where(int line, std::size_t column);
// At most 40 bytes of the text, for messages.
std::string excerpt(std::string_view text);

}  // namespace mx::gcode_scan
