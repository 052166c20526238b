#include "gcode/gcode_block.h"

#include <cmath>

namespace mx {

const GcodeWord* GcodeBlock::find(char letter) const {
  for (const auto& w : words)
    if (w.letter == letter && w.address.size() <= 1 && w.has_value) return &w;
  return nullptr;
}

const GcodeWord* GcodeBlock::findAddress(std::string_view address) const {
  for (const auto& w : words)
    if (w.address == address && w.has_value) return &w;
  return nullptr;
}

bool GcodeBlock::hasG(int number) const {
  for (const auto& w : words)
    if (w.address == "G" && std::abs(w.value - number) < 1e-9) return true;
  return false;
}

}  // namespace mx
