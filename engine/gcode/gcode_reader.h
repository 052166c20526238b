#pragma once
// Reads a part program in its dialect (gcode_dialect.h; detected when not named).
// ISO and its relatives (sinumerik, linuxcnc): the common subset G0 G1 G2 G3 G4 G17 G20 G21 G90 G91
// with the words F S X Y Z I J P (and N sequence numbers), the common M words M0-M9 and M30 (known, not
// interpreted), comments in parentheses or after ';', a block delete '/' and a tape marker '%'. Letters
// are case-insensitive, spaces between words are optional ("G1X10F200"), numbers may carry a sign and
// a decimal point ("-.5", "10.").
//  - sinumerik adds G64 (continuous path), S1= (the spindle's address), CR= (arc radius), CYCLE...(...)
//    and MSG(...) calls (kept verbatim, not interpreted), NAME=value assignments and $ variables;
//  - linuxcnc adds G64 (path blending), M52 P (the adaptive-feed input), #<name> and #123 parameters
//    (assignments kept verbatim), o-word subroutine and flow lines (kept verbatim, warned about);
//  - words whose value is an expression ("X[#1*2]", "X=IC(5)") are kept verbatim and warned about.
// heidenhain: Klartext blocks (heidenhain_lexer.cpp). Other G and M codes, T words and unknown
// keywords are kept verbatim in the block and listed as a warning with line, column and text; text
// that cannot be split into words at all (stray characters such as '@' or '$' in ISO) refuses the
// program with its line and column.
// Line ends: "\n" and "\r\n" (kept per line); a last line without line end is kept and warned about.
// Comment bytes (UTF-8 or not) are kept unchanged.
// Limits: a line is at most kMaxGcodeLineLength bytes, and a word's value lies in the range of its
// letter (GcodeWordLimits); past them the program is refused, since no machine runs it and the models
// would run without bound on it.
#include <optional>
#include <string>
#include <string_view>

#include "core/input_file.h"
#include "gcode/gcode_program.h"

namespace mx {

inline constexpr std::size_t kMaxGcodeLineLength = 4096;  // bytes, line end excluded
// A part program file: 16 MB holds about half a million blocks, far more than any override runs.
inline constexpr InputFileLimit kPartProgramFileLimit{16 * kMegabyte, "a part program"};

// Word ranges, in program units (mm or inch, per minute).
struct GcodeWordLimits {
  static constexpr double kMaxSpindleRpm = 1e5;  // S in [0, 1e5] rpm
  static constexpr double kMaxFeed = 1e6;        // F in [0, 1e6] per minute
  static constexpr double kMaxCoordinate = 1e6;  // |X|, |Y|, |Z|, |I|, |J| <= 1e6
  static constexpr double kMaxDwellS = 1e5;      // P in [0, 1e5] s
};

class GcodeReader {
 public:
  // Parses program text in `dialect`, or in the detected one (detectDialect). Throws InvalidInput, with
  // the line and column, for an undetectable dialect, a line longer than kMaxGcodeLineLength, text that
  // cannot be split into words, or a word outside GcodeWordLimits; unknown words are kept and warned
  // about. An empty text gives an empty ISO program.
  static GcodeProgram parse(std::string_view text, std::optional<GcodeDialect> dialect = std::nullopt);
  // Reads and parses a file; throws InvalidInput ("gcode file = <path>: cannot be read", or over
  // kPartProgramFileLimit, or not a regular file) on failure.
  static GcodeProgram readFile(const std::string& path, std::optional<GcodeDialect> dialect = std::nullopt);
};

}  // namespace mx
