#pragma once
// The per-dialect lexers behind GcodeReader: each splits one block's text into words and comments,
// marks the editable F and S words and where they may be inserted, and appends warnings.
#include <vector>

#include "gcode/gcode_block.h"
#include "gcode/gcode_dialect.h"

namespace mx::gcode_lex {

// ISO, Sinumerik and LinuxCNC (iso_lexer.cpp).
void lexIsoFamilyLine(GcodeBlock& block, GcodeDialect dialect, std::vector<GcodeWarning>& warnings);
// Heidenhain Klartext (heidenhain_lexer.cpp).
void lexHeidenhainLine(GcodeBlock& block, std::vector<GcodeWarning>& warnings);

}  // namespace mx::gcode_lex
