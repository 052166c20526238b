#pragma once
// Stabilisation diagram (Peeters et al. 2004, sec. 3): the physical poles of each model order, each
// compared with the nearest-frequency pole of the previous order.
//   stable            |df| / f <= frequency_tol and |dzeta| / zeta <= damping_tol
//   frequency-stable  only |df| / f <= frequency_tol
//   unstable          neither, or no pole at the previous order
// Physical: Im lambda > 0, Re lambda < 0, from_hz <= f <= to_hz, 0 < zeta < max_damping.
#include <complex>
#include <vector>

namespace mx {

enum class PoleStability { Unstable, FrequencyStable, Stable };

struct StabilityCriteria {
  double frequency_tol = 0.01;
  double damping_tol = 0.05;
  double max_damping = 0.3;
};

struct DiagramPole {
  std::complex<double> lambda;  // continuous-time pole [rad/s]
  double frequency_hz = 0.0;    // |lambda| / (2 pi)
  double damping_ratio = 0.0;   // -Re lambda / |lambda|
  PoleStability stability = PoleStability::Unstable;
  int stable_orders = 1;            // consecutive orders up to this one over which the pole stayed stable
  int frequency_stable_orders = 1;  // the same for the frequency alone
};

struct DiagramOrder {
  int order = 0;
  std::vector<DiagramPole> poles;  // sorted by frequency
};

struct StabilisationDiagram {
  std::vector<DiagramOrder> orders;  // increasing order
};

std::vector<DiagramPole> physicalPoles(const std::vector<std::complex<double>>& lambdas, double from_hz, double to_hz,
                                       const StabilityCriteria& criteria);

// Sets stability and the run lengths of `current` against the previous order's poles.
void classifyPoles(std::vector<DiagramPole>& current, const std::vector<DiagramPole>& previous,
                   const StabilityCriteria& criteria);

// One pole per cluster of the poles stable over at least min_orders consecutive orders, or
// frequency-stable over min_orders + 1 (noisy data scatter the damping more than the frequency): the
// medians of the cluster's frequencies and damping ratios. Neighbours in frequency belong to one
// cluster when their relative gap is <= max(frequency_tol, zeta / 2), zeta the lighter damping of the
// two (a quarter of its half-power bandwidth).
std::vector<std::complex<double>> stablePoles(const StabilisationDiagram& diagram, int min_orders,
                                              const StabilityCriteria& criteria);

}  // namespace mx
