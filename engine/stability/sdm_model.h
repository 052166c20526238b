#pragma once
// Linearised regenerative milling model in semi-discretized form (Insperger & Stepan 2002, 2004).
//
// Per mode r on axis a (x or y), with the scaled state (q_r, q_r'/omega_r):
//   q_r'' + 2 zeta_r omega_r q_r' + omega_r^2 q_r = (omega_r^2 / k_r) F_a,   x = sum q_x-modes, y = sum q_y-modes.
// Regenerative force (Rubio et al. 2006 eq. 2, 3, 7 about the static chip):
//   F(t) = b H(t) (r(t) - r(t - T)),  r = (x, y),
//   H(t) = K_t sum_j g(phi_j) [ -(sc + K_r s^2)   -(c^2 + K_r sc) ]
//                             [  s^2 - K_r sc       sc - K_r c^2   ],  s = sin phi_j, c = cos phi_j,
// phi_j = Omega t + j 2 pi / n_t, g = 1 inside [entry, exit] (Immersion::contains).
// So z' = (A0 + b P H C) z - b P H r(t - T).
// Real cutters (docs/fidelity.md, "Real cutters"): tooth j at Omega t + toothAngleRad(j) has its own delay
// tau_j = pitch_j / Omega (Altintas, Engin & Budak 1999; Insperger & Stepan 2004, sec. 5), so
//   F(t) = b sum_j H_j(t) (r(t) - r(t - tau_j)),
// and with variable pitch the coefficients repeat only once per revolution: the principal period is then
// the revolution, discretised by n_t m steps (m per mean tooth period). A helix lags the edge at height z
// by kappa z (kappa = tan(helix) / R), so H_j is averaged over the lag psi in [0, kappa b]; over a step this
// is exact in closed form (second antiderivatives of the trigonometric integrands), or by midpoint slices.
// Teeth of equal delay share one stencil; a delay of d = m_j - e steps (0 <= e < 1) is interpolated
// through the samples around r_{i-m_j} with the nodes shifted by e. On step i, [t_i, t_i + dt], dt = T/m, H is replaced
// by its time average H_i over the step (evaluated in closed form; it depends only on i, not on speed), and r(t - T),
// in the step's normalised time s = (t - t_i)/dt, by the Lagrange polynomial of degree p through r_{i-m+j-back} at s =
// j - back, j = 0 .. p (delay order p: 1 is the first-order SDM, the line through r_{i-m}, r_{i-m+1}; 3, back = 1, the
// cubic through r_{i-m-1} .. r_{i-m+2}, whose error falls as (omega dt)^4 instead of (omega dt)^2; Insperger, Stepan &
// Turi 2008). With l_j(s) = sum_k a_jk s^k the step maps come from one exponential of the augmented matrix (Van Loan
// 1978) with the chain of integrators u_0' = u_1, .., u_p' = 0 in s:
//   exp([ L dt  -R dt  0 .. 0 ; 0  0  I .. ; .. ; 0 .. 0 ]) = [ Phi  F_0 .. F_p ; ... ],
//   F_k = integral_0^1 e^{L dt (1 - s)} (-R dt) s^k / k! ds,  L = A0 + b P H_i C, R = b P H_i,
//   Phi_i = Phi, G_ij = sum_k a_jk k! F_k.
// Process damping (the C_i / V model; docs/fidelity.md, "Process damping"): each engaged edge adds the
// force -(C_i b / V) n_j n_j^T r'(t), n_j = (sin phi_j, cos phi_j), so L gains -(C_i b / V) P N_i C_v with
// N_i the step average of sum_j g(phi_j) n_j n_j^T (the same integrals as H_i) and C_v the velocity output.
#include <Eigen/Dense>
#include <vector>

#include "model/milling_setup.h"
#include "stability/sdm_monodromy.h"
#include "stability/semi_discretization.h"

namespace mx {

class SdmModel {
 public:
  // steps_per_tooth_period m (per mean tooth period with variable pitch); delay_order p in
  // [1, kMaxSdmDelayOrder], at most m (requireDelayOrder); helix_slices as SdmOptions::helix_slices.
  SdmModel(const MillingSetup& setup, int steps_per_tooth_period, int delay_order = 1,
           int helix_slices = kExactHelixSlices);
  // Throws InvalidInput naming the order and its allowed range for `steps` steps per period.
  static void requireDelayOrder(int delay_order, int steps_per_period);

  int steps() const { return steps_; }  // per principal period
  int stepsPerToothPeriod() const { return steps_per_tooth_; }
  int delayOrder() const { return order_; }
  int historyBack() const { return order_ / 2; }  // samples before r_{i-m}: 0, 1, 1 for p = 1, 2, 3
  int modalStates() const { return static_cast<int>(a0_.rows()); }
  int teeth() const { return teeth_; }
  int delayGroups() const { return static_cast<int>(groups_.size()); }  // distinct tooth delays
  // A tooth period with uniform pitch, a revolution with variable pitch.
  double principalPeriodS(double spindle_rev_per_s) const { return teeth_per_period_ / (spindle_rev_per_s * teeth_); }

  // H_i [N/m^2] of the straight edges: time average of H(t) over step i; zero when no tooth is in cut.
  const Eigen::Matrix2d& averagedCoefficient(int step) const { return h_[static_cast<size_t>(step)]; }
  bool inCut(int step) const { return in_cut_[static_cast<size_t>(step)]; }

  // exp(A0 dt): the step map of every step with no tooth in cut; compute once per speed.
  Eigen::MatrixXd freeStep(double spindle_rev_per_s) const;
  // Fills `out` with the step maps at (speed, depth); free_step = freeStep(speed).
  void build(double spindle_rev_per_s, double depth_m, const Eigen::MatrixXd& free_step, SdmMonodromy& out) const;

  // exp(-sigma_min T): spectral radius at zero depth, sigma_min = smallest zeta*omega_n (0 if rigid).
  double freeDecay(double spindle_rev_per_s) const;

 private:
  // Teeth that share one delay of (base - shift) steps, 0 <= shift < 1.
  // The step averages of a group's teeth: H_i and the normal projector N_i.
  struct StepCoefficients {
    Eigen::Matrix2d h = Eigen::Matrix2d::Zero();
    Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
  };
  struct DelayGroup {
    int base = 0;
    double shift = 0.0;
    std::vector<double> tooth_angles;
    Eigen::MatrixXd lagrange;                // a_jk: node j, power k of s
    std::vector<StepCoefficients> straight;  // of these teeth with straight edges
  };
  // The coefficients of each group at depth b (the helix lag depends on b); zero where no edge cuts.
  std::vector<std::vector<StepCoefficients>> coefficientsAt(double depth_m) const;
  std::vector<StepCoefficients> groupCoefficients(const DelayGroup& g, double depth_m) const;

  MillingSetup setup_;
  int steps_per_tooth_ = 0;
  int teeth_per_period_ = 1;
  int steps_ = 0;
  int order_ = 1;
  int teeth_ = 1;
  int helix_slices_ = kExactHelixSlices;
  int depth_ = 0;  // history depth: the largest sample offset
  double dphi_ = 0.0;
  std::vector<DelayGroup> groups_;
  double min_decay_rate_ = 0.0;
  Eigen::MatrixXd a0_;                          // N x N
  Eigen::Matrix<double, Eigen::Dynamic, 2> p_;  // N x 2 force input
  Eigen::MatrixXd c_;                           // 2 x N position output
  Eigen::MatrixXd velocity_;                    // 2 x N velocity output
  std::vector<Eigen::Matrix2d> h_;
  std::vector<bool> in_cut_;
};

}  // namespace mx
