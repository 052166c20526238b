#pragma once
// Writes a GcodeProgram back in its own dialect, changing only F and S words and appending comments.
// Blocks are never dropped or reordered; a block without an edit is written byte-for-byte as read (its
// line end too).
//  - F / S: the block's editable word (GcodeBlock::feed_word, speed_word) gets the new number in place;
//    its address and separator are kept ("f 250" -> "f 180", "S1=2000" -> "S1=2400", Heidenhain
//    "F AUTO" -> "F180"). Otherwise " F<value>" / " S<value>" is inserted where the block takes one
//    (ISO: after its last word; Heidenhain: F before the M words of a motion block, S after the tool
//    axis of a TOOL CALL); a block of a dialect that takes no such word is refused.
//  - comment: appended at the end of the line: " (text)" in ISO and LinuxCNC, '(' ')' in the text
//    becoming '[' ']'; " ; text" in Heidenhain and Sinumerik, or " text" inside a comment that already
//    runs to the end of the line. It is cut where the block would pass kMaxGcodeLineLength.
//  - header: the project, the controller and the date. ISO, LinuxCNC, Sinumerik: comment lines at the
//    top (after a leading '%' tape marker line, and after Sinumerik's "%_N_" and ";$PATH=" lines) with
//    the program's own line end. Heidenhain numbers its blocks, so no line is inserted: the header is a
//    comment on the BEGIN PGM block.
// Numbers are written with std::to_chars (locale independent), trailing zeros removed.
#include <limits>
#include <string>
#include <vector>

#include "gcode/gcode_program.h"

namespace mx {

struct GcodeBlockEdit {
  double feed = std::numeric_limits<double>::quiet_NaN();       // new F, program units per minute; NaN: keep
  double speed_rpm = std::numeric_limits<double>::quiet_NaN();  // new S [rpm]; NaN: keep
  int feed_decimals = 1;
  int speed_decimals = 0;
  std::string comment;  // appended when not empty

  bool empty() const { return !(feed == feed) && !(speed_rpm == speed_rpm) && comment.empty(); }
};

struct GcodeHeader {
  std::string project;
  std::string controller;
  std::string date;
};

class GcodeWriter {
 public:
  // edits: empty (no change) or exactly one per block; throws InvalidInput otherwise.
  static std::string write(const GcodeProgram& program, const std::vector<GcodeBlockEdit>& edits,
                           const GcodeHeader* header = nullptr);
  // The header lines alone (each ending with eol), as ISO comments or, with semicolon, ';' comments.
  static std::string headerText(const GcodeHeader& header, const std::string& eol, bool semicolon = false);
  // Fixed notation with at most `decimals` decimals, trailing zeros and a bare '.' removed.
  static std::string formatNumber(double value, int decimals);
  // The text with '(' ')' replaced by '[' ']' and line breaks by spaces.
  static std::string sanitizeComment(const std::string& text);
  // The block's text with the edit applied (line end not included). Throws InvalidInput for a non-finite
  // F or S, or a word the block cannot take in its dialect.
  static std::string applyEdit(const GcodeBlock& block, const GcodeBlockEdit& edit,
                               GcodeDialect dialect = GcodeDialect::Iso);
};

}  // namespace mx
