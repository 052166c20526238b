#pragma once
// Tooth-period monodromy map of the semi-discretization (Insperger & Stepan 2004, IJNME 61:117-141;
// higher-order delay interpolation: Insperger, Stepan & Turi 2008, JSV 313:334-341), applied
// implicitly as m step maps.
//
// The delayed displacement over step i is interpolated through the p + 1 samples r_{i-m+j-back},
// j = 0 .. p (p = 1, back = 0: the first-order SDM's line through r_{i-m}, r_{i-m+1}). Discrete state
// (dimension N + 2(m + back), N = 2 * modes):
//   Z_i = [ z_i ; r_{i-m-back} ; ... ; r_{i-1} ],   r = C z = (x, y) displacements.
// Step i:  z_{i+1} = Phi_i z_i + sum_j G_ij r_{i-m+j-back},   r_i = C z_i.
// One application maps [z_0; r_{-m-back} .. r_{-1}] to [z_m; r_{-back} .. r_{m-1}]; every sample a
// step needs is known by then as long as p <= m + back.
#include <Eigen/Dense>
#include <complex>
#include <vector>

namespace mx {

class SdmMonodromy {
 public:
  using StepInput = Eigen::Matrix<double, Eigen::Dynamic, 2>;

  // Sizes the map for `steps` steps whose delayed term uses `stencil` samples starting `back` samples
  // before r_{i-m}; every step starts as a free-vibration step.
  void reset(const Eigen::MatrixXd& output_c, int steps, int back = 0, int stencil = 2);
  // Step matrices shared by every step with no tooth in cut (every G = 0).
  void setFreeStep(const Eigen::MatrixXd& phi) { free_phi_ = phi; }
  // Step i with a tooth in cut; g[j] multiplies r_{i-m+j-back} (stencil entries).
  void setCutStep(int i, const Eigen::MatrixXd& phi, const std::vector<StepInput>& g);

  int steps() const { return steps_; }
  int modalStates() const { return static_cast<int>(c_.cols()); }
  int dimension() const { return modalStates() + 2 * (steps_ + back_); }

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
  std::vector<std::vector<StepInput>> g_;
  int steps_ = 0;
  int back_ = 0;
  int stencil_ = 2;
  mutable Eigen::Matrix<double, 2, Eigen::Dynamic> history_;  // r_{-m-back} .. r_{m-1}
  mutable Eigen::VectorXd z_, z_next_;
};

}  // namespace mx
