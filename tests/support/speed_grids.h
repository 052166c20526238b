#pragma once
// Test helper: spindle-speed grids in rev/s, given in rpm, and the lowest limit on a lobe envelope.
#include <algorithm>
#include <vector>

#include "model/milling_setup.h"
#include "stability/lobe_diagram.h"

namespace mx::test {

// From `from_rpm` to `to_rpm` in steps of `step_rpm`, as the lobe computations take them (rev/s).
inline std::vector<double> rpmGrid(double from_rpm, double to_rpm, double step_rpm) {
  return SpeedGrid{from_rpm / 60.0, to_rpm / 60.0, step_rpm / 60.0}.values();
}

// `count` evenly spaced speeds from `from_rpm` to `to_rpm` inclusive (rev/s).
inline std::vector<double> rpmGridOfCount(double from_rpm, double to_rpm, int count) {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) out.push_back(rpmToRevPerS(from_rpm + (to_rpm - from_rpm) * i / (count - 1)));
  return out;
}

// The smallest limit depth, LobeDiagram::kNone when there is none.
inline double minFinite(const std::vector<double>& limits) {
  double m = LobeDiagram::kNone;
  for (double b : limits) m = std::min(m, b);
  return m;
}

}  // namespace mx::test
