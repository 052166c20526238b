#pragma once
// Writes a GcodeProgram back, changing only F and S words and appending comments. Blocks are never
// dropped or reordered; a block without an edit is written byte-for-byte as read (its line end too).
//  - F / S: an existing word of that letter is replaced in place (the letter's case is kept); otherwise
//    " F<value>" / " S<value>" is inserted after the block's last word, before its comments.
//  - comment: appended at the end of the line as " (text)"; '(' and ')' in the text become '[' ']'.
//  - header: comment lines with the project, the controller and the date, inserted at the top (after a
//    leading '%' tape marker line), with the program's own line end.
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
  // The header lines alone (each ending with eol).
  static std::string headerText(const GcodeHeader& header, const std::string& eol);
  // Fixed notation with at most `decimals` decimals, trailing zeros and a bare '.' removed.
  static std::string formatNumber(double value, int decimals);
  // The text with '(' ')' replaced by '[' ']' and line breaks by spaces.
  static std::string sanitizeComment(const std::string& text);
  // The block's text with the edit applied (line end not included).
  static std::string applyEdit(const GcodeBlock& block, const GcodeBlockEdit& edit);
};

}  // namespace mx
