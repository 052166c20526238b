#include "control/force_plant.h"

#include <cmath>
#include <string>

#include "core/invalid_input.h"

namespace mx {

namespace {
constexpr double kPi = 3.14159265358979323846;

void requirePositive(const char* field, double value, const char* unit) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw InvalidInput(std::string("force plant: ") + field + " = " + std::to_string(value) + " " + unit +
                       ": must be finite and > 0");
}
}  // namespace

double immersionFunction(double start_angle_rad, double exit_angle_rad, int teeth) {
  if (teeth < 1) throw InvalidInput("immersion function: teeth = " + std::to_string(teeth) + ": must be >= 1");
  if (!(start_angle_rad >= 0.0 && start_angle_rad < exit_angle_rad && exit_angle_rad <= kPi))
    throw InvalidInput("immersion function: (start_angle, exit_angle) = (" + std::to_string(start_angle_rad) + ", " +
                       std::to_string(exit_angle_rad) + ") rad: must satisfy 0 <= start < exit <= pi");
  return teeth / (2.0 * kPi) * (std::cos(start_angle_rad) - std::cos(exit_angle_rad));
}

double defaultProcessTimeConstant(int teeth, double spindle_rev_s) {
  if (teeth < 1) throw InvalidInput("process time constant: teeth = " + std::to_string(teeth) + ": must be >= 1");
  requirePositive("spindle_rev_s", spindle_rev_s, "rev/s");
  return 1.0 / (2.0 * teeth * spindle_rev_s);
}

void validateCuttingProcess(const CuttingProcess& p) {
  requirePositive("cutting_pressure_Pa", p.cutting_pressure_Pa, "N/m^2");
  requirePositive("spindle_rev_s", p.spindle_rev_s, "rev/s");
  requirePositive("drive_time_constant_s", p.drive_time_constant_s, "s");
  if (!std::isfinite(p.process_time_constant_s))
    throw InvalidInput("force plant: process_time_constant_s = " + std::to_string(p.process_time_constant_s) +
                       " s: must be finite (> 0, or <= 0 for the default half tooth period)");
  immersionFunction(p.start_angle_rad, p.exit_angle_rad, p.teeth);
}

double processTimeConstant(const CuttingProcess& p) {
  return p.process_time_constant_s > 0.0 ? p.process_time_constant_s
                                         : defaultProcessTimeConstant(p.teeth, p.spindle_rev_s);
}

double spindlePeriod(const CuttingProcess& p) {
  requirePositive("spindle_rev_s", p.spindle_rev_s, "rev/s");
  return 1.0 / p.spindle_rev_s;
}

ForcePlant makeForcePlant(const CuttingProcess& p, double depth_m) {
  validateCuttingProcess(p);
  if (!(depth_m >= 0.0) || !std::isfinite(depth_m))
    throw InvalidInput("force plant: depth = " + std::to_string(depth_m) + " m: must be finite and >= 0");
  const double a = immersionFunction(p.start_angle_rad, p.exit_angle_rad, p.teeth);
  ForcePlant plant;
  plant.gain_N_s_per_m = p.cutting_pressure_Pa * depth_m * a / (p.spindle_rev_s * p.teeth);
  plant.tau_m_s = p.drive_time_constant_s;
  plant.tau_c_s = processTimeConstant(p);
  return plant;
}

StateSpace2 ForcePlant::stateSpace() const {
  StateSpace2 s;
  // The gain sits in C, so that the matrix exponential only sees the time constants (better conditioned).
  s.A << -1.0 / tau_m_s, 0.0, 1.0 / tau_c_s, -1.0 / tau_c_s;
  s.B << 1.0 / tau_m_s, 0.0;
  s.C << 0.0, gain_N_s_per_m;
  return s;
}

}  // namespace mx
