#pragma once
// A synthetic lobe diagram whose answers are known by hand: two parabolic lobes, A: b = 1 + (n-100)^2/625
// mm and B: b = 2 + (n-200)^2/833.33 mm, meeting at 5 mm at 150 rev/s; the envelope min(A, B) sampled
// every 1 rev/s from 80 to 250 rev/s.
#include <algorithm>

#include "stability/lobe_diagram.h"

namespace mx::test {

inline double twoLobesEnvelopeMm(double n) {
  return std::min(1.0 + (n - 100.0) * (n - 100.0) / 625.0, 2.0 + (n - 200.0) * (n - 200.0) / (2500.0 / 3.0));
}

inline LobeDiagram twoLobes() {
  LobeDiagram d;
  for (int n = 80; n <= 250; ++n) {
    d.speed_rev_per_s.push_back(n);
    d.envelope_depth_m.push_back(twoLobesEnvelopeMm(n) * 1e-3);
    d.envelope_chatter_hz.push_back(0.0);
  }
  return d;
}

}  // namespace mx::test
