#pragma once
// Engine test fixtures: the seed's tools in SI (Rubio et al. 2006 R1/R2; Insperger benchmark), and
// measured FRFs sampled from known modes.
#include <cmath>
#include <numbers>

#include "model/milling_setup.h"

namespace mx::test {

inline MillingSetup makeSetup(int teeth, double diameter_m, double kt, double kr, ModalAxis x, ModalAxis y,
                              MillingDirection dir, double radial_ratio) {
  MillingSetup s;
  s.teeth = teeth;
  s.diameter_m = diameter_m;
  s.tangential_coefficient_pa = kt;
  s.radial_ratio = kr;
  s.modes_x = std::move(x);
  s.modes_y = std::move(y);
  s.direction = dir;
  s.radial_depth_m = radial_ratio * diameter_m;
  s.immersion = Immersion::fromRadialDepth(s.radial_depth_m, diameter_m, dir);
  return s;
}

inline MillingSetup rubioR1() {
  return makeSetup(3, 0.030, 6e8, 0.3, {{603.0, 0.039, 5.59e6}}, {{666.0, 0.035, 5.715e6}}, MillingDirection::Up, 1.0);
}
// q* of the 2006 example for R1: 5800 rpm, b = 0.4924 mm, s_t = 0.2722 mm.
inline const OperatingPoint kRubioQStar{5800.0 / 60.0, 0.4924e-3, 0.2722e-3};
inline MillingSetup rubioR2() {
  return makeSetup(2, 0.0127, 6e8, 0.07, {{900.03, 0.0139, 0.879e6}}, {{911.65, 0.0138, 0.971e6}}, MillingDirection::Up,
                   1.0);
}
// Insperger & Stepan benchmark: 922 Hz, zeta 0.011, m = 0.03993 kg on x; y rigid; K_n/K_t = 1/3.
inline MillingSetup insperger(double radial_ratio) {
  const double w = 2.0 * std::numbers::pi * 922.0;
  return makeSetup(2, 0.020, 6e8, 1.0 / 3.0, {{922.0, 0.011, 0.03993 * w * w}}, {}, MillingDirection::Down,
                   radial_ratio);
}

// receptance(modes, i 2 pi f) at the lines f_from, f_from + step, ..., f_to [Hz].
inline MeasuredAxis sampledAxis(const ModalAxis& modes, double f_from_hz, double f_to_hz, double step_hz) {
  MeasuredAxis axis;
  const int lines = static_cast<int>(std::lround((f_to_hz - f_from_hz) / step_hz)) + 1;
  for (int i = 0; i < lines; ++i) {
    const double f = f_from_hz + step_hz * i;
    axis.frequency_hz.push_back(f);
    axis.h_m_per_n.push_back(receptance(modes, {0.0, 2.0 * std::numbers::pi * f}));
  }
  return axis;
}

}  // namespace mx::test
