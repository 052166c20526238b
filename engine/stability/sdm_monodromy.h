#pragma once
// Tooth-period monodromy map of the first-order semi-discretization (Insperger & Stepan 2004,
// IJNME 61:117-141), applied implicitly as m step maps.
//
// Discrete state (dimension N + 2m, N = 2 * modes):
//   Z_i = [ z_i ; r_{i-m} ; r_{i-m+1} ; ... ; r_{i-1} ],   r = C z = (x, y) displacements.
// Step i:  z_{i+1} = Phi_i z_i + G0_i r_{i-m} + G1_i r_{i-m+1},   r_i = C z_i.
// After m steps the whole delayed history is replaced, so one application maps
// [z_0; r_{-m} .. r_{-1}] to [z_m; r_0 .. r_{m-1}].
#include <Eigen/Dense>
#include <complex>
#include <vector>

namespace mx {

class SdmMonodromy {
 public:
  using StepInput = Eigen::Matrix<double, Eigen::Dynamic, 2>;

  // Sizes the map; every step starts as a free-vibration step.
  void reset(const Eigen::MatrixXd& output_c, int steps);
  // Step matrices shared by every step with no tooth in cut (G0 = G1 = 0).
  void setFreeStep(const Eigen::MatrixXd& phi) { free_phi_ = phi; }
  // Step i with a tooth in cut.
  void setCutStep(int i, const Eigen::MatrixXd& phi, const StepInput& g0, const StepInput& g1);

  int steps() const { return steps_; }
  int modalStates() const { return static_cast<int>(c_.cols()); }
  int dimension() const { return modalStates() + 2 * steps_; }

  // out = M in. Not reentrant (uses member work buffers).
  void apply(const Eigen::Ref<const Eigen::VectorXd>& in, Eigen::Ref<Eigen::VectorXd> out) const;
  // Explicit monodromy matrix (columns M e_k), for the dense fallback and tests.
  Eigen::MatrixXd dense() const;

  // Chatter frequency [Hz] of the Floquet mode (mu, v) of a tooth period T: the history samples
  // r(t_j), t_j = (j - m) T/m, are r(t) = mu^(t/T) p(t) with p T-periodic; the dominant Fourier
  // harmonic k of p gives f = |arg(mu)/(2 pi) + k| / T. Returns 0 if mu or v vanishes.
  double chatterFrequencyHz(std::complex<double> mu, const Eigen::VectorXcd& v, double period_s) const;

 private:
  Eigen::MatrixXd c_;           // 2 x N output (position) matrix
  Eigen::MatrixXd free_phi_;    // exp(A0 dt)
  std::vector<int> cut_index_;  // per step: index into the cut-step tables or -1 (free)
  std::vector<Eigen::MatrixXd> phi_;
  std::vector<StepInput> g0_, g1_;
  int steps_ = 0;
  mutable Eigen::Matrix<double, 2, Eigen::Dynamic> history_;  // r_{-m} .. r_{m-1}
  mutable Eigen::VectorXd z_, z_next_;
};

}  // namespace mx
