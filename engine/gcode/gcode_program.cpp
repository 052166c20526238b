#include "gcode/gcode_program.h"

namespace mx {

std::string GcodeProgram::text() const {
  std::size_t n = 0;
  for (const auto& b : blocks) n += b.text.size() + b.eol.size();
  std::string out;
  out.reserve(n);
  for (const auto& b : blocks) {
    out += b.text;
    out += b.eol;
  }
  return out;
}

std::string GcodeProgram::lineEnd() const {
  for (const auto& b : blocks)
    if (!b.eol.empty()) return b.eol;
  return "\n";
}

}  // namespace mx
