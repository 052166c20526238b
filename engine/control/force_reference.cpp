#include "control/force_reference.h"

#include <cmath>

#include "core/invalid_input.h"

namespace mx {

namespace {
constexpr double kPi = 3.14159265358979323846;

void requirePositive(const char* field, double v) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw InvalidInput(std::string("force reference: ") + field + " = " + std::to_string(v) +
                       ": must be finite and > 0");
}
}  // namespace

ForceReference forceReferenceFromLimits(const ToolForceLimits& l) {
  ForceReference r;
  const bool has_breakage = l.breakage_force_N > 0.0, has_power = l.spindle_power_W > 0.0;
  if (!has_breakage && !has_power)
    throw InvalidInput("force reference: breakage_force_N = " + std::to_string(l.breakage_force_N) +
                       " and spindle_power_W = " + std::to_string(l.spindle_power_W) + ": at least one must be > 0");
  if (has_breakage) {
    requirePositive("breakage_force_N", l.breakage_force_N);
    if (!(l.safety_factor > 0.0 && l.safety_factor <= 1.0))
      throw InvalidInput("force reference: safety_factor = " + std::to_string(l.safety_factor) + ": must be in (0, 1]");
    r.breakage_limit_N = l.safety_factor * l.breakage_force_N;
  }
  if (has_power) {
    requirePositive("spindle_power_W", l.spindle_power_W);
    requirePositive("tool_diameter_m", l.tool_diameter_m);
    requirePositive("spindle_rev_s", l.spindle_rev_s);
    r.power_limit_N = l.spindle_power_W / (kPi * l.tool_diameter_m * l.spindle_rev_s);
  }
  if (has_breakage && (!has_power || r.breakage_limit_N <= r.power_limit_N)) {
    r.force_N = r.breakage_limit_N;
    r.binding = "breakage";
  } else {
    r.force_N = r.power_limit_N;
    r.binding = "power";
  }
  return r;
}

}  // namespace mx
