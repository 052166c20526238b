#pragma once
// Static (rigid-tool) cutting forces, power, torque and MRR (Rubio et al. 2006, eq. 2-5;
// Pareto paper eq. 8: P = v * sum_j F_tj with v = pi D N / 60).
#include <vector>

#include "model/axial_slices.h"
#include "model/milling_setup.h"

namespace mx {

// Average directional factors alpha_ij of the zeroth-order approximation (Budak & Altintas 1998):
// F = (n_t K_t b / 4 pi) [alpha] Delta, integrated over [phi_st, phi_ex].
struct DirectionalFactors {
  double xx = 0.0, xy = 0.0, yx = 0.0, yy = 0.0;
};
DirectionalFactors averageDirectionalFactors(const Immersion& immersion, double radial_ratio);

// Force on the tool from one tooth at angle phi with chip thickness h (h <= 0 or outside the
// immersion gives zero), with the edge forces (Altintas 2000, eq. 2.22):
//   F_t = b (K_t h + K_te),  F_r = b (K_r K_t h + K_re),  F_a = b (K_ac h + K_ae),
//   F_x = -F_t cos phi - F_r sin phi,  F_y = F_t sin phi - F_r cos phi,  F_z = F_a.
struct ToothForce {
  double tangential_n = 0.0;
  double fx_n = 0.0;
  double fy_n = 0.0;
  double fz_n = 0.0;
};
ToothForce toothForce(const MillingSetup& setup, double depth_m, double phi_rad, double chip_m);
// The parts of toothForce proportional to b h (per unit b h, [N/m^2]) and to b alone (the edge forces,
// per unit b, [N/m]), at phi whether or not it lies in the immersion.
ToothForce chipForcePerArea(const MillingSetup& setup, double phi_rad);
ToothForce edgeForcePerDepth(const MillingSetup& setup, double phi_rad);

// Sum over the teeth at cutter rotation angle theta (tooth j at theta + toothAngleRad(j)), rigid tool.
struct StaticForce {
  double tangential_sum_n = 0.0;  // sum_j F_tj
  double fx_n = 0.0;
  double fy_n = 0.0;
  double fz_n = 0.0;
  double resultant() const;  // the lateral |(F_x, F_y)|, which bends the tool
};

// The rigid-tool cut of a real cutter (docs/fidelity.md, "Real cutters"): each tooth's slices at their
// helix lag, each tooth's feed proportional to its pitch, and each chip changed by the runout. The chip
// of tooth j is the least over the k = 1 .. n_t teeth ahead of it that last passed (Kline & DeVor 1983):
//   h_j = max(0, min_k [ s_t (n_t / 2 pi) (pitch_j + .. + pitch_{j+k-1}) sin phi + rho_j - rho_{j+k} ]).
// With uniform pitch and no runout, h_j = s_t sin phi (Rubio et al. 2006, eq. 7 for a rigid tool).
class StaticCut {
 public:
  // `slices` as axialSlices (0: the default for the depth).
  StaticCut(const MillingSetup& setup, const OperatingPoint& point, int slices = 0);
  StaticForce at(double theta_rad) const;

 private:
  struct Pass {
    double feed_factor = 1.0;  // (n_t / 2 pi) times the pitches from tooth j to tooth j + k
    double runout_m = 0.0;     // rho_j - rho_{j+k}
  };
  const MillingSetup& setup_;
  double feed_m_ = 0.0;
  std::vector<AxialSlice> slices_;
  std::vector<double> tooth_angle_;
  std::vector<std::vector<Pass>> passes_;  // per tooth, in growing feed_factor
  std::vector<double> least_runout_m_;     // per tooth: the least runout_m of its passes
};

StaticForce staticForce(const MillingSetup& setup, const OperatingPoint& point, double theta_rad);

struct CutPerformance {
  double peak_power_w = 0.0;  // max over the principal period (a tooth period; a revolution for variable pitch)
  double mean_power_w = 0.0;
  double peak_torque_nm = 0.0;      // max of (D/2) sum F_t
  double peak_force_n = 0.0;        // max lateral resultant |(F_x, F_y)|
  double peak_axial_force_n = 0.0;  // max |F_z|
  double mrr_m3_per_s = 0.0;        // a b s_t n_t N
  double cutting_speed_m_per_s = 0.0;
};
CutPerformance evaluateCut(const MillingSetup& setup, const OperatingPoint& point);

// Peak power and peak resultant force per unit (b s_t) at depth b and feed s_t: the power is
// proportional to N (v = pi D N) and the force independent of it. Without runout and edge forces both are
// independent of s_t, and with straight teeth of b too; the helix lowers them as b grows, the runout and
// the edge forces raise them at small s_t. Used for the power- and force-limit curves (Pareto paper eq. 8 and Module
// II).
struct PeakPerDepthFeed {
  double power_w_per_rev_per_s = 0.0;  // P / (N b s_t) [W / (rev/s m^2)]
  double force_n = 0.0;                // |F|_max / (b s_t) [N / m^2]
};
PeakPerDepthFeed peakPerDepthFeed(const MillingSetup& setup, double depth_m, double feed_m);

}  // namespace mx
