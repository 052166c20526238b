#pragma once
// Shared benchmark inputs: the 2006 paper's tool R1 (one mode per axis) in full-immersion up-milling.
#include "model/milling_setup.h"

namespace mx::bench {

inline MillingSetup toolR1() {
  MillingSetup s;
  s.tool_id = "R1";
  s.teeth = 3;
  s.diameter_m = 0.030;
  s.tangential_coefficient_pa = 6e8;
  s.radial_ratio = 0.3;
  s.modes_x = {{603.0, 0.039, 5.59e6}};
  s.modes_y = {{666.0, 0.035, 5.715e6}};
  s.direction = MillingDirection::Up;
  s.radial_depth_m = s.diameter_m;
  s.immersion = Immersion::fromRadialDepth(s.radial_depth_m, s.diameter_m, s.direction);
  return s;
}

// Insperger & Stepan's benchmark: one x mode (922 Hz, zeta 0.011, k = 1.34005e6 N/m), K_t = 6e8 N/m^2,
// K_r = 1/3, 2 teeth, down milling, radial immersion a/D.
inline MillingSetup insperger(double a_over_d) {
  MillingSetup s;
  s.tool_id = "INSPERGER";
  s.teeth = 2;
  s.diameter_m = 0.020;
  s.tangential_coefficient_pa = 6e8;
  s.radial_ratio = 1.0 / 3.0;
  s.modes_x = {{922.0, 0.011, 1.3400496480507487e6}};
  s.direction = MillingDirection::Down;
  s.radial_depth_m = a_over_d * s.diameter_m;
  s.immersion = Immersion::fromRadialDepth(s.radial_depth_m, s.diameter_m, s.direction);
  return s;
}

}  // namespace mx::bench
