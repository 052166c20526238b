#pragma once
// A part program as read: its dialect, every line of the file as a block, in order, and the reader's
// warnings (unknown words and lines, unclosed comments, a last line without line end). Nothing is
// dropped: concatenating text + eol of all blocks gives the file back byte-for-byte.
#include <string>
#include <vector>

#include "gcode/gcode_block.h"
#include "gcode/gcode_dialect.h"

namespace mx {

struct GcodeProgram {
  DialectDetection dialect;  // the dialect read, and the line that told it (line 0: named or ISO by default)
  std::vector<GcodeBlock> blocks;
  std::vector<GcodeWarning> warnings;

  // The program's bytes, reassembled from the blocks (identical to the file read).
  std::string text() const;
  // "\r\n" when the first line ends so, otherwise "\n" (used for inserted header lines).
  std::string lineEnd() const;
};

}  // namespace mx
