#include "stability/zoa_validity.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

namespace mx {

namespace {

// Angle tolerance so that slotting with two equal teeth (cut angle = pitch = pi) counts as continuous.
constexpr double kAngleToleranceRad = 1e-9;

double maxPitchRad(const MillingSetup& setup) {
  double p = 0.0;
  for (int j = 0; j < setup.teeth; ++j) p = std::max(p, setup.pitchRad(j));
  return p;
}

double radialImmersionOfAngle(double cut_angle_rad) {
  return 0.5 * (1.0 - std::cos(std::min(cut_angle_rad, std::numbers::pi)));
}

}  // namespace

ZoaValidity zoaValidity(const MillingSetup& setup) {
  setup.validateGeometry();
  ZoaValidity v;
  const double cut_angle = setup.immersion.exit_rad - setup.immersion.entry_rad;
  const double max_pitch = maxPitchRad(setup);
  v.radial_immersion = radialImmersionOfAngle(cut_angle);
  v.min_radial_immersion = max_pitch >= std::numbers::pi ? 1.0 : radialImmersionOfAngle(max_pitch);
  const bool continuous = cut_angle >= max_pitch - kAngleToleranceRad;
  v.accurate = continuous && setup.uniformPitch();
  std::ostringstream reason;
  reason << std::fixed << std::setprecision(2) << "radial immersion a/D = " << v.radial_immersion;
  if (max_pitch > std::numbers::pi + kAngleToleranceRad)
    reason << ": with a pitch of " << max_pitch * 180.0 / std::numbers::pi
           << " deg > 180 deg no cut is continuous, so only semi-discretization is valid";
  else if (!setup.uniformPitch())
    reason << ", variable pitch: the zeroth-order approximation averages out the once-per-revolution modulation "
              "of the unequal teeth and misses the lobes it adds (up to 8.6 times too deep), so only "
              "semi-discretization is valid";
  else if (v.accurate)
    reason << " >= " << v.min_radial_immersion
           << ": a tooth is always in the cut, so the zeroth-order approximation is accurate"
           << (setup.helix_rad != 0.0 ? " (it ignores the helix, which semi-discretization models)" : "");
  else
    reason << " < " << v.min_radial_immersion
           << ": the cut is intermittent, so only semi-discretization is valid (the zeroth-order approximation "
              "misses the flip lobes)";
  v.reason = reason.str();
  return v;
}

}  // namespace mx
