#include "gcode/gcode_block.h"

#include <cmath>

namespace mx {

const GcodeWord* GcodeBlock::find(char letter) const {
  for (const auto& w : words)
    if (w.letter == letter) return &w;
  return nullptr;
}

bool GcodeBlock::hasG(int number) const {
  for (const auto& w : words)
    if (w.letter == 'G' && std::abs(w.value - number) < 1e-9) return true;
  return false;
}

}  // namespace mx
