#pragma once
// Stability boundary b_lim at one spindle speed for the semi-discretization: the smallest depth where
// f(b) = log rho(b) + delta T crosses zero (rho = dominant multiplier modulus). f(0) < 0 whenever
// delta < smallest zeta*omega_n, since rho(0) = exp(-zeta omega_n T).
#include <Eigen/Dense>
#include <complex>

#include "stability/sdm_arnoldi.h"
#include "stability/sdm_model.h"
#include "stability/semi_discretization.h"

namespace mx {

struct SdmBoundaryPoint {
  double depth_m = 0.0;                       // LobeDiagram::kNone if stable up to max_depth
  std::complex<double> multiplier{0.0, 0.0};  // dominant multiplier at depth_m
  double chatter_hz = 0.0;
  int evaluations = 0;  // spectral-radius evaluations used
};

class SdmBoundarySearch {
 public:
  SdmBoundarySearch(const SdmModel& model, const SdmOptions& options);

  // guess_depth <= 0 or non-finite: cold start from an analytic estimate (coldGuess).
  // lowest_known_m: smallest b_lim found so far (e.g. at other speeds); the island scan below the
  // continued crossing b* reaches down to half of min(b*, lowest_known_m).
  SdmBoundaryPoint solve(double spindle_rev_per_s, double guess_depth_m, double lowest_known_m = LobeDiagram::kNone);

  // Rough lower estimate of the lobe minimum, single-mode zeroth-order form per mode:
  // 4 pi k zeta (1 + zeta) / (n_t K_t ||alpha||_F), alpha = averageDirectionalFactors.
  static double coldGuess(const MillingSetup& setup, double max_depth_m);
  void setColdGuess(double depth_m) { cold_guess_ = depth_m; }

 private:
  struct Sample {
    double depth = 0.0;
    double f = 0.0;  // log rho + delta T
    SdmEigenpair pair;
  };
  Sample evaluate(double depth_m);
  Sample brent(Sample lo, Sample hi);
  bool scanBelow(const Sample& top, double floor_depth_m, Sample& lo, Sample& hi);
  bool maximiseNear(const Sample& below, const Sample& peak, const Sample& above, Sample& hi);
  SdmBoundaryPoint finish(const Sample& s);

  const SdmModel& model_;
  SdmOptions options_;
  SdmArnoldi arnoldi_;
  SdmMonodromy map_;
  double built_depth_m_ = -1.0;  // the depth map_ holds
  Eigen::MatrixXd free_step_;
  Eigen::VectorXd warm_;
  double speed_ = 0.0;
  double period_ = 0.0;
  double cold_guess_ = 0.0;
  int evaluations_ = 0;
};

}  // namespace mx
