#pragma once
// The controller dialects a part program may be written in, and their detection from the program's
// text. The override writes a program back in the dialect it was read in.
//  - iso: ISO 6983 / Fanuc-style G-code (G0-G3, F, S; comments in parentheses or after ';');
//  - heidenhain: Heidenhain conversational (Klartext): BEGIN PGM, TOOL CALL ... S, L, CC/C, CR, CT,
//    RND, CHF, FMAX, END PGM; comments after ';';
//  - sinumerik: Siemens Sinumerik: the ISO core plus G64, CYCLE...(...) calls, S1= spindle addresses,
//    CR= arc radii, ';' comments;
//  - linuxcnc: LinuxCNC RS274NGC: the ISO core plus M52 (adaptive feed input), #<named> and #123
//    parameters, o-word subroutines, (MSG,...) comments.
// Detection looks for each dialect's own syntax outside comments (docs/part-programs.md lists the
// markers). A program with no marker is ISO when its first block starts with a letter word; a program
// with markers of two dialects, or whose first block is no G-code at all, cannot be detected.
#include <optional>
#include <string>
#include <string_view>

namespace mx {

enum class GcodeDialect { Iso, Heidenhain, Sinumerik, LinuxCnc };

// "iso", "heidenhain", "sinumerik", "linuxcnc".
std::string_view dialectName(GcodeDialect dialect);
// The controller family as a machinist names it ("ISO / Fanuc", "Heidenhain Klartext", ...).
std::string_view dialectTitle(GcodeDialect dialect);
std::optional<GcodeDialect> dialectFromName(std::string_view name);
// "iso, heidenhain, sinumerik, linuxcnc": the allowed names, for error messages.
std::string dialectNames();

struct DialectDetection {
  GcodeDialect dialect = GcodeDialect::Iso;
  int line = 0;          // 1-based line of the first marker; 0 when none (ISO by default)
  std::string evidence;  // the marker found there ("BEGIN PGM", "CYCLE832(", ...); empty when none
};

// Throws InvalidInput naming the first line that cannot be attributed: a marker of a second dialect,
// or, without markers, a first block that is not G-code.
DialectDetection detectDialect(std::string_view text);

}  // namespace mx
