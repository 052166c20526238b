#include "model/milling_setup.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mx {

Immersion Immersion::fromRadialDepth(double radial_depth_m, double diameter_m, MillingDirection direction) {
  const double ratio = std::clamp(radial_depth_m / diameter_m, 0.0, 1.0);
  if (direction == MillingDirection::Up) return {0.0, std::acos(1.0 - 2.0 * ratio)};
  return {std::acos(2.0 * ratio - 1.0), std::numbers::pi};
}

bool Immersion::contains(double phi_rad) const {
  const double two_pi = 2.0 * std::numbers::pi;
  double phi = std::fmod(phi_rad, two_pi);
  if (phi < 0.0) phi += two_pi;
  return phi >= entry_rad && phi <= exit_rad;
}

double MillingSetup::toothPitchRad() const {
  return 2.0 * std::numbers::pi / teeth;
}

}  // namespace mx
