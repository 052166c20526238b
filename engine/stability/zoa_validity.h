#pragma once
// Which stability method is valid for a tool in its cut, for the ZOA/SDM switch. The zeroth-order
// approximation keeps only the mean of the time-varying directional factors (Altintas & Budak 1995); it
// is accurate where their higher harmonics are small, i.e. where the cut is continuous. In an intermittent
// cut the harmonics dominate (flip lobes, Insperger & Stepan 2004) and only the semi-discretization is
// valid. With variable pitch the coefficients also vary once per revolution, and the ZOA averages that
// away too: on a 4-tooth slot, 4000-24000 rpm by 250 rpm, against the SDM, it keeps the lowest b_lim
// within 2 % but misses the lobes the pitch adds, per speed by up to 28 % (R1's modes) and 8.6 times
// (Insperger's lightly damped mode) for 70/110 deg; 85/95 deg: 11 % and 2.8 times. So a variable-pitch
// tool is never "accurate" for the ZOA, whatever its immersion.
//
// Rule: the ZOA is accurate when some tooth is always in the cut, cut angle phi_ex - phi_st >= the largest
// pitch, i.e. a/D >= (1 - cos(max pitch)) / 2: uniform 2 teeth a/D >= 1, 3 teeth 0.75, 4 teeth 0.5,
// 5 teeth 0.35, 6 teeth 0.25. Measured, ZOA against SDM (cubic, automatic steps) on R1's two modes with
// 2-4 uniform teeth, up and down milling, a/D 0.05-1, 3000-15000 rpm every 100 rpm
// (stability.zoa_validity): where the rule holds, the lowest b_lim differs by at most 6.4 % and the median
// pointwise difference is at most 5.0 %; where it fails, up to 153 % and 43 % (2 teeth down milling,
// a/D 0.4). A fixed a/D threshold does not work: a/D >= 0.3 still gives 30 % (3 teeth down, a/D 0.5) and
// 129 % (2 teeth down, a/D 0.5). The rule is conservative for up milling with 4 teeth (a/D 0.3: 3.1 %).
#include <string>

#include "model/milling_setup.h"

namespace mx {

struct ZoaValidity {
  bool accurate = false;              // uniform pitch and radial_immersion >= min_radial_immersion
  double radial_immersion = 0.0;      // a/D from the immersion angles: (1 - cos(phi_ex - phi_st)) / 2
  double min_radial_immersion = 0.0;  // (1 - cos(max pitch)) / 2, 1 when the largest pitch is >= 180 deg
  std::string reason;                 // one sentence for the user: the immersion and the method to use
};

ZoaValidity zoaValidity(const MillingSetup& setup);

}  // namespace mx
