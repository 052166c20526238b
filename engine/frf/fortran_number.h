#pragma once
// Numbers of Fortran-formatted records (E13.5, E20.12, D formats): [sign] digits [. digits]
// [E|e|D|d [sign] digits]. Fixed-width fields of negative numbers may touch ("-1.2E+00-3.4E-01"),
// so a number ends where the next sign begins. Not recognised: NaN/Inf, and the E-less three-digit
// exponent ("1.2-100") that some Fortran runtimes print.
#include <cstddef>
#include <string_view>

namespace mx {

// Scans the number starting at text[pos]. On success stores it in value, moves pos past it and returns
// true; the number must end at the end of text, a blank or a sign. On failure (no number, overflow)
// returns false and leaves pos unchanged.
bool scanFortranNumber(std::string_view text, std::size_t& pos, double& value);

// The whole of text (blanks around allowed) as one number.
bool parseFortranNumber(std::string_view text, double& value);

// Index of the first non-blank (space, tab) character at or after pos; text.size() if none.
std::size_t skipBlanks(std::string_view text, std::size_t pos);

// The blank-delimited token at pos (for messages).
std::string_view tokenAt(std::string_view text, std::size_t pos);

}  // namespace mx
