#pragma once
// The cutter as the time-domain simulation sees it (docs/fidelity.md, "Real cutters"):
//  - edges: each tooth's axial slices (Altintas 2000, sec. 3.3), slice k of tooth j at the angle
//    phi_j - lag_k = theta + toothAngleRad(j) - helixLagRad(z_k), cutting a depth b / n_s;
//  - passes: pass k (1-based) of tooth j cuts the surface that tooth j + k left tau_jk earlier, where
//    the cutter turned A_jk = pitch_j + ... + pitch_{j+k-1}; its chip (the generalised eq. 7) is
//      h_jk = (s_t n_t A_jk / 2 pi + x(t) - x(t - tau_jk)) sin phi + (y(t) - y(t - tau_jk)) cos phi
//             + rho_j - rho_{j+k},
//    so the mean feed per tooth stays s_t. The slices of one tooth share its passes (the helix lags
//    every tooth alike).
// Uniform pitch without runout keeps one set of passes for all teeth (A_k = k 2 pi / n_t): the
// regenerative model of eq. 7 with one delay per pass.
#include <cstddef>
#include <vector>

#include "model/milling_setup.h"

namespace mx {

struct CutterEdge {
  double angle_rad = 0.0;       // from tooth 0's tip, in the direction of rotation
  double depth_fraction = 1.0;  // the edge's share of the axial depth b
  int pass_set = 0;             // index of its tooth's passes in ToothPasses (0 when shared)
};

// True when all teeth share one set of passes: uniform pitch and no runout.
bool teethSharePasses(const MillingSetup& setup);

// The straight teeth (one slice each) or, with `slices` >= 1 (0 = defaultAxialSlices), the slices of
// a helical cutter over the depth b. Straight uniform teeth sit at exactly j 2 pi / n_t.
std::vector<CutterEdge> cutterEdges(const MillingSetup& setup, double depth_m, int slices);
std::vector<CutterEdge> straightTeeth(const MillingSetup& setup);

// Per pass set s and pass k (0-based, index s * passes + k): the delay in mean tooth periods
// (A n_t / 2 pi; exactly k + 1 when shared), the static feed s_t times that, and the runout term.
struct ToothPasses {
  int sets = 1;
  int passes = 1;
  std::vector<double> delay_tooth_periods;
  std::vector<double> feed_m;
  std::vector<double> runout_m;
  std::size_t index(int set, int pass) const {
    return static_cast<std::size_t>(set) * static_cast<std::size_t>(passes) + static_cast<std::size_t>(pass);
  }
  double maxDelayToothPeriods() const;
};

ToothPasses toothPasses(const MillingSetup& setup, double feed_per_tooth_m, int passes);

// The rigid tool's chip as the static reference: the smallest over the n_t surfaces left by the other
// teeth in the last revolution (with runout a tooth may cut less than s_t, or nothing). One pass when
// the teeth share their passes: h = s_t sin phi.
ToothPasses rigidToolPasses(const MillingSetup& setup, double feed_per_tooth_m);

}  // namespace mx
