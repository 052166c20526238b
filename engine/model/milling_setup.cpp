#include "model/milling_setup.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>

#include "core/invalid_input.h"

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

double MillingSetup::pitchRad(int tooth) const {
  return pitch_rad.empty() ? toothPitchRad() : pitch_rad[static_cast<std::size_t>(tooth)];
}

double MillingSetup::toothAngleRad(int tooth) const {
  if (pitch_rad.empty()) return tooth * toothPitchRad();
  double angle = 0.0;
  for (int k = 0; k < tooth; ++k) angle += pitch_rad[static_cast<std::size_t>(k)];
  return angle;
}

double MillingSetup::runoutM(int tooth) const {
  return runout_m.empty() ? 0.0 : runout_m[static_cast<std::size_t>(tooth)];
}

bool MillingSetup::uniformPitch() const {
  const double mean = toothPitchRad();
  return std::all_of(pitch_rad.begin(), pitch_rad.end(), [mean](double p) { return std::abs(p - mean) <= 1e-9; });
}

bool MillingSetup::hasRunout() const {
  return std::any_of(runout_m.begin(), runout_m.end(), [](double r) { return r != 0.0; });
}

double MillingSetup::helixLagRad(double height_m) const {
  return diameter_m > 0.0 ? 2.0 * height_m * std::tan(helix_rad) / diameter_m : 0.0;
}

namespace {
std::string number(double v) {
  std::ostringstream s;
  s << std::setprecision(10) << v;
  return s.str();
}

void requireLength(const char* field, std::size_t length, int teeth) {
  if (length != 0 && length != static_cast<std::size_t>(teeth))
    throw InvalidInput(std::string(field) + " has " + std::to_string(length) +
                       " entries: must have one per tooth (teeth = " + std::to_string(teeth) + ")");
}
}  // namespace

void MillingSetup::validateGeometry() const {
  constexpr double kDeg = 180.0 / std::numbers::pi;
  if (teeth < 1 || teeth > kMaxTeeth)
    throw InvalidInput("teeth = " + std::to_string(teeth) + " is outside [1, " + std::to_string(kMaxTeeth) + "]");
  if (!(std::abs(helix_rad) < 0.5 * std::numbers::pi))
    throw InvalidInput("helix = " + number(helix_rad * kDeg) + " deg is outside (-90, 90) deg");
  requireLength("pitch", pitch_rad.size(), teeth);
  requireLength("runout", runout_m.size(), teeth);
  double sum = 0.0;
  for (std::size_t j = 0; j < pitch_rad.size(); ++j) {
    if (!(pitch_rad[j] > 0.0 && pitch_rad[j] < 2.0 * std::numbers::pi))
      throw InvalidInput("pitch[" + std::to_string(j) + "] = " + number(pitch_rad[j] * kDeg) +
                         " deg is outside (0, 360) deg");
    sum += pitch_rad[j];
  }
  if (!pitch_rad.empty() && !(std::abs(sum - 2.0 * std::numbers::pi) <= kPitchSumToleranceRad))
    throw InvalidInput("pitch sums to " + number(sum * kDeg) + " deg: must sum to 360 deg within 1e-6 deg");
  for (std::size_t j = 0; j < runout_m.size(); ++j)
    if (!(std::abs(runout_m[j]) < 0.25 * diameter_m))
      throw InvalidInput("runout[" + std::to_string(j) + "] = " + number(runout_m[j] * 1e6) +
                         " um is outside (-D/4, D/4) = (" + number(-0.25e6 * diameter_m) + ", " +
                         number(0.25e6 * diameter_m) + ") um");
}

void MillingSetup::validateCoefficients() const {
  const std::pair<const char*, double> fields[] = {{"K_t [N/m^2]", tangential_coefficient_pa},
                                                   {"K_r", radial_ratio},
                                                   {"K_te [N/m]", tangential_edge_n_per_m},
                                                   {"K_re [N/m]", radial_edge_n_per_m},
                                                   {"K_ac [N/m^2]", axial_coefficient_pa},
                                                   {"K_ae [N/m]", axial_edge_n_per_m},
                                                   {"C_i [N/m] (process damping)", process_damping_n_per_m}};
  for (const auto& [name, value] : fields)
    if (!(value >= 0.0 && std::isfinite(value)))
      throw InvalidInput(std::string(name) + " = " + number(value) + ": must be finite and >= 0");
}

double MillingSetup::processDampingPerDepth(double spindle_rev_per_s) const {
  if (process_damping_n_per_m == 0.0) return 0.0;
  return process_damping_n_per_m / (std::numbers::pi * diameter_m * spindle_rev_per_s);
}

}  // namespace mx
