#pragma once
// Reads a G-code part program: the common subset G0 G1 G2 G3 G4 G17 G20 G21 G90 G91 with the words
// F S X Y Z I J P (and N sequence numbers), comments in parentheses or after ';'. Letters are
// case-insensitive, spaces between words are optional ("G1X10F200"), numbers may carry a sign and a
// decimal point ("-.5", "10."). Anything else (other G codes, M, T, R words, macro syntax, stray
// characters) is kept verbatim in the block and listed as a warning with line, column and text.
// Line ends: "\n" and "\r\n" (kept per line); a last line without line end is kept and warned about.
// Comment bytes (UTF-8 or not) are kept unchanged.
#include <string>
#include <string_view>

#include "gcode/gcode_program.h"

namespace mx {

class GcodeReader {
 public:
  // Parses program text. Never throws for content; an empty text gives an empty program.
  static GcodeProgram parse(std::string_view text);
  // Reads and parses a file; throws InvalidInput ("gcode file = <path>: cannot be read") on failure.
  static GcodeProgram readFile(const std::string& path);

 private:
  static void lexLine(GcodeBlock& block, std::vector<GcodeWarning>& warnings);
};

}  // namespace mx
