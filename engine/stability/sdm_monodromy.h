#pragma once
// Tooth-period monodromy map of the semi-discretization (Insperger & Stepan 2004, IJNME 61:117-141;
// higher-order delay interpolation: Insperger, Stepan & Turi 2008, JSV 313:334-341), applied
// implicitly as m step maps.
//
// Every step's delayed terms are samples of the displacement history r = C z: step i adds
// G_i,d r_{i-d} for a list of offsets d >= 0 (for one delay of m steps interpolated through p + 1
// samples starting `back` before r_{i-m}, d = m + back - j, j = 0 .. p; a variable-pitch cutter has one
// such stencil per distinct tooth delay). Discrete state, D = the largest offset (history depth):
//   Z_i = [ z_i ; r_{i-D} ; ... ; r_{i-1} ].
// Step i:  z_{i+1} = Phi_i z_i + sum_d G_i,d r_{i-d},   r_i = C z_i.
// One application (m steps, one principal period) maps [z_0; r_{-D} .. r_{-1}] to [z_m; r_{m-D} .. r_{m-1}].
#include <Eigen/Dense>
#include <complex>
#include <utility>
#include <vector>

namespace mx {

class SdmMonodromy {
 public:
  using StepInput = Eigen::Matrix<double, Eigen::Dynamic, 2>;

  struct DelayedTerm {
    int offset = 0;  // d: the term multiplies r_{i-d}
    StepInput g;
  };

  // Sizes the map for `steps` steps and a history of `depth` samples (the largest offset); every step
  // starts as a free-vibration step.
  void reset(const Eigen::MatrixXd& output_c, int steps, int depth);
  // Step matrices shared by every step with no tooth in cut (no delayed term).
  void setFreeStep(const Eigen::MatrixXd& phi) { free_phi_ = phi; }
  // Step i with a tooth in cut; offsets in [0, depth].
  void setCutStep(int i, const Eigen::MatrixXd& phi, std::vector<DelayedTerm> terms);

  int steps() const { return steps_; }
  int modalStates() const { return static_cast<int>(c_.cols()); }
  int historyDepth() const { return depth_; }
  int dimension() const { return modalStates() + 2 * depth_; }

  // out = M in. Not reentrant (uses member work buffers).
  void apply(const Eigen::Ref<const Eigen::VectorXd>& in, Eigen::Ref<Eigen::VectorXd> out) const;
  // Explicit monodromy matrix (columns M e_k), for the dense fallback and tests.
  Eigen::MatrixXd dense() const;

  // Chatter frequency [Hz] of the Floquet mode (mu, v) of the principal period T: the samples
  // r(t_j), t_j = j T/m over one period, are r(t) = mu^(t/T) p(t) with p T-periodic; the dominant Fourier
  // harmonic k of p gives f = |arg(mu)/(2 pi) + k| / T. The samples are the mode's stored history when
  // it spans a period, else the map's images of Re v and Im v. Returns 0 if mu or v vanishes.
  double chatterFrequencyHz(std::complex<double> mu, const Eigen::VectorXcd& v, double period_s) const;

 private:
  // r over one principal period of the Floquet mode v (2 x m).
  Eigen::Matrix<std::complex<double>, 2, Eigen::Dynamic> periodSamples(const Eigen::VectorXcd& v) const;

  Eigen::MatrixXd c_;           // 2 x N output (position) matrix
  Eigen::MatrixXd free_phi_;    // exp(A0 dt)
  std::vector<int> cut_index_;  // per step: index into the cut-step tables or -1 (free)
  std::vector<Eigen::MatrixXd> phi_;
  std::vector<std::vector<DelayedTerm>> terms_;
  int steps_ = 0;
  int depth_ = 0;
  mutable Eigen::Matrix<double, 2, Eigen::Dynamic> history_;  // r_{-D} .. r_{m-1}
  mutable Eigen::VectorXd z_, z_next_;
};

}  // namespace mx
