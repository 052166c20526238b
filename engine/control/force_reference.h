#pragma once
// Force reference from the tool's limits (Pareto paper, Rule 3; 2006 paper, section 4): the resultant force must not
// exceed what the tool resists (breakage) nor what the spindle can drive (power), whichever binds.
//   F_break = safety_factor * breakage_force
//   F_power = P_available / v,  v = pi D N (cutting speed), treating the controlled resultant force as the
//             tangential force that loads the spindle (conservative: |F_t| <= |F|).
#include <string>

namespace mx {

struct ToolForceLimits {
  double breakage_force_N = 0.0;  // <= 0: not given
  double safety_factor = 1.0;     // in (0, 1]
  double spindle_power_W = 0.0;   // <= 0: not given
  double tool_diameter_m = 0.0;
  double spindle_rev_s = 0.0;
};

struct ForceReference {
  double force_N = 0.0;
  double breakage_limit_N = 0.0;  // 0 when not given
  double power_limit_N = 0.0;     // 0 when not given
  std::string binding;            // "breakage" or "power"
};

// InvalidInput when neither limit is given, or a given limit has invalid companions (field, value, range).
ForceReference forceReferenceFromLimits(const ToolForceLimits& limits);

}  // namespace mx
