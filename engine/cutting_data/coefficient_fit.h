#pragma once
// Cutting coefficients from test cuts, the average-force method (Altintas, Manufacturing Automation,
// 2nd ed., section 2.5): the mechanistic model per unit of axial depth
//   F_t = K_tc h + K_te,   F_r = K_rc h + K_re,   F_a = K_ac h + K_ae,   h = c sin(phi),
// resolved with our convention (milling_setup.h: feed along +x, phi clockwise from +y)
//   F_x = -F_t cos(phi) - F_r sin(phi),   F_y = F_t sin(phi) - F_r cos(phi),   F_z = F_a,
// and averaged over a revolution of n_t uniformly pitched teeth cutting from phi_st to phi_ex, is linear
// in the feed per tooth c:
//   Fx_mean = (n_t a / 2 pi) [-(K_tc c) S_sc - (K_rc c) S_ss - K_te S_c - K_re S_s]
//   Fy_mean = (n_t a / 2 pi) [ (K_tc c) S_ss - (K_rc c) S_sc + K_te S_s - K_re S_c]
//   Fz_mean = (n_t a / 2 pi) [ (K_ac c) S_s + K_ae (phi_ex - phi_st)]
// with S_sc, S_ss, S_c, S_s the integrals of sin cos, sin^2, cos and sin over [phi_st, phi_ex]. A straight
// line through each axis's mean forces against c gives a slope and an intercept; the slopes give the
// cutting coefficients and the intercepts the edge coefficients (slotting: Fx = -n_t a K_rc c / 4 -
// n_t a K_re / pi, Fy = n_t a K_tc c / 4 + n_t a K_te / pi). The helix does not change the means.
// SI units: forces in N, lengths in m, K_*c in N/m^2, K_*e in N/m.
#include <array>
#include <vector>

#include "model/milling_setup.h"

namespace mx {

struct TestCut {
  double feed_per_tooth_m = 0.0;
  double fx_n = 0.0, fy_n = 0.0, fz_n = 0.0;  // mean forces on the tool over whole revolutions
};

struct TestCutSetup {
  int teeth = 0;
  double diameter_m = 0.0;
  double depth_m = 0.0;       // axial depth a
  double radial_ratio = 1.0;  // a_e / D in (0, 1]; 1: slotting
  MillingDirection direction = MillingDirection::Down;
};

// A straight line F = slope c + intercept through one axis's mean forces, least squares.
struct AxisLine {
  double slope = 0.0, intercept = 0.0;  // N/m, N
  double slope_stderr = 0.0, intercept_stderr = 0.0;
  double r2 = 0.0;  // 1 when every cut lies on the line (also when the forces do not vary)
  std::vector<double> residuals_n;
};

struct CuttingCoefficients {
  double Ktc_pa = 0.0, Krc_pa = 0.0, Kac_pa = 0.0;  // N/m^2
  double Kte_n_per_m = 0.0, Kre_n_per_m = 0.0, Kae_n_per_m = 0.0;
};

struct CoefficientFit {
  CuttingCoefficients coefficients;
  // Half-widths of the 95 % confidence intervals (Student t with cuts - 2 degrees of freedom, the axes'
  // lines independent); 0 with two cuts, which a line fits exactly.
  CuttingCoefficients half_width_95;
  std::array<AxisLine, 3> lines;                                           // x, y, z
  double Kr() const { return coefficients.Krc_pa / coefficients.Ktc_pa; }  // the seeds' K_r
};

// InvalidInput naming the field: fewer than two cuts, fewer than two distinct feeds, a feed <= 0, a
// force that is not finite, or a setup outside teeth 1..100, D, a > 0, a_e/D in (0, 1].
CoefficientFit fitCuttingCoefficients(const TestCutSetup& setup, const std::vector<TestCut>& cuts);

// The model's mean forces of a cut (the forward direction of the fit; synthetic test cuts).
TestCut meanCutForces(const TestCutSetup& setup, const CuttingCoefficients& k, double feed_per_tooth_m);

// Two-sided 95 % quantile of Student's t with `dof` >= 1 degrees of freedom.
double studentT95(int dof);

}  // namespace mx
