#pragma once
// Static (rigid-tool) cutting forces, power, torque and MRR (Rubio et al. 2006, eq. 2-5;
// Pareto paper eq. 8: P = v * sum_j F_tj with v = pi D N / 60).
#include "model/milling_setup.h"

namespace mx {

// Average directional factors alpha_ij of the zeroth-order approximation (Budak & Altintas 1998):
// F = (n_t K_t b / 4 pi) [alpha] Delta, integrated over [phi_st, phi_ex].
struct DirectionalFactors {
  double xx = 0.0, xy = 0.0, yx = 0.0, yy = 0.0;
};
DirectionalFactors averageDirectionalFactors(const Immersion& immersion, double radial_ratio);

// Force on the tool from one tooth at angle phi with chip thickness h (h <= 0 or outside the
// immersion gives zero): F_t = K_t b h, F_r = K_r F_t, F_x = -F_t cos phi - F_r sin phi,
// F_y = F_t sin phi - F_r cos phi.
struct ToothForce {
  double tangential_n = 0.0;
  double fx_n = 0.0;
  double fy_n = 0.0;
};
ToothForce toothForce(const MillingSetup& setup, double depth_m, double phi_rad, double chip_m);

// Sum over the teeth at cutter rotation angle theta (tooth j at theta + j * pitch), rigid tool.
struct StaticForce {
  double tangential_sum_n = 0.0;  // sum_j F_tj
  double fx_n = 0.0;
  double fy_n = 0.0;
  double resultant() const;
};
StaticForce staticForce(const MillingSetup& setup, const OperatingPoint& point, double theta_rad);

struct CutPerformance {
  double peak_power_w = 0.0;  // max over a tooth period of v * sum F_t
  double mean_power_w = 0.0;
  double peak_torque_nm = 0.0;  // max of (D/2) sum F_t
  double peak_force_n = 0.0;    // max resultant |F|
  double mrr_m3_per_s = 0.0;    // a b s_t n_t N
  double cutting_speed_m_per_s = 0.0;
};
CutPerformance evaluateCut(const MillingSetup& setup, const OperatingPoint& point);

// Peak power per unit (b * s_t): P = b s_t * powerPerDepthFeed; used for power-limit curves.
double peakPowerPerDepthFeed(const MillingSetup& setup, double spindle_rev_per_s);
// Peak resultant force per unit (b * s_t): |F|_max = b s_t * peakForcePerDepthFeed (independent of N);
// bounds the Rule 3 tool-force limit (Pareto paper, Module II).
double peakForcePerDepthFeed(const MillingSetup& setup);

}  // namespace mx
