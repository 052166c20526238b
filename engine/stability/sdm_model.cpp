#include "stability/sdm_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unsupported/Eigen/MatrixFunctions>

namespace mx {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Integrals of s^2, sc, c^2 over [a, b] (s = sin phi, c = cos phi).
struct TrigIntegrals {
  double s2 = 0.0, sc = 0.0, c2 = 0.0;
  void add(double a, double b) {
    if (b <= a) return;
    const double d2 = std::sin(2.0 * b) - std::sin(2.0 * a);
    s2 += 0.5 * (b - a) - 0.25 * d2;
    c2 += 0.5 * (b - a) + 0.25 * d2;
    sc += 0.5 * (std::sin(b) * std::sin(b) - std::sin(a) * std::sin(a));
  }
};

// Adds the part of the tooth-angle interval [a, a + len] (len < 2 pi) inside the cut window
// [entry, exit] taken modulo 2 pi, as Immersion::contains does.
void addInCut(const Immersion& im, double a, double len, TrigIntegrals& acc) {
  const double entry = std::clamp(im.entry_rad, 0.0, kTwoPi);
  const double exit = std::clamp(im.exit_rad, 0.0, kTwoPi);
  a -= kTwoPi * std::floor(a / kTwoPi);
  const double b = a + len;
  for (double shift : {0.0, kTwoPi}) acc.add(std::max(a, entry + shift), std::min(b, exit + shift));
}

}  // namespace

SdmModel::SdmModel(const MillingSetup& setup, int steps_per_period) : steps_(steps_per_period), teeth_(setup.teeth) {
  struct Dof {
    const Mode* mode;
    int axis;
  };
  std::vector<Dof> dofs;
  for (const Mode& m : setup.modes_x) dofs.push_back({&m, 0});
  for (const Mode& m : setup.modes_y) dofs.push_back({&m, 1});
  const auto n = static_cast<Eigen::Index>(2 * dofs.size());
  a0_ = Eigen::MatrixXd::Zero(n, n);
  p_ = Eigen::Matrix<double, Eigen::Dynamic, 2>::Zero(n, 2);
  c_ = Eigen::MatrixXd::Zero(2, n);
  min_decay_rate_ = dofs.empty() ? 0.0 : std::numeric_limits<double>::infinity();
  for (size_t r = 0; r < dofs.size(); ++r) {
    const Mode& mode = *dofs[r].mode;
    const double w = mode.angularFrequency();
    const auto i = static_cast<Eigen::Index>(2 * r);
    // (q, v = q'/w):  q' = w v,  v' = -w q - 2 zeta w v + (w / k) F_axis.
    a0_(i, i + 1) = w;
    a0_(i + 1, i) = -w;
    a0_(i + 1, i + 1) = -2.0 * mode.damping_ratio * w;
    p_(i + 1, dofs[r].axis) = w / mode.stiffness_n_per_m;
    c_(dofs[r].axis, i) = 1.0;
    min_decay_rate_ = std::min(min_decay_rate_, mode.decayRate());
  }

  // Averaged H_i: step i spans cutter angles [i dphi, (i + 1) dphi], dphi = pitch / m.
  const double pitch = setup.toothPitchRad();
  const double dphi = pitch / steps_;
  const double kt = setup.tangential_coefficient_pa;
  const double kr = setup.radial_ratio;
  h_.assign(static_cast<size_t>(steps_), Eigen::Matrix2d::Zero());
  in_cut_.assign(static_cast<size_t>(steps_), false);
  for (int i = 0; i < steps_; ++i) {
    TrigIntegrals t;
    for (int j = 0; j < teeth_; ++j) addInCut(setup.immersion, i * dphi + j * pitch, dphi, t);
    Eigen::Matrix2d& h = h_[static_cast<size_t>(i)];
    h << -(t.sc + kr * t.s2), -(t.c2 + kr * t.sc), t.s2 - kr * t.sc, t.sc - kr * t.c2;
    h *= kt / dphi;
    in_cut_[static_cast<size_t>(i)] = (t.s2 + t.c2) > 1e-12 * dphi;
    if (!in_cut_[static_cast<size_t>(i)]) h.setZero();
  }
}

Eigen::MatrixXd SdmModel::freeStep(double spindle_rev_per_s) const {
  const double dt = toothPeriodS(spindle_rev_per_s) / steps_;
  return (a0_ * dt).exp();
}

double SdmModel::freeDecay(double spindle_rev_per_s) const {
  return a0_.rows() == 0 ? 0.0 : std::exp(-min_decay_rate_ * toothPeriodS(spindle_rev_per_s));
}

void SdmModel::build(double spindle_rev_per_s, double depth_m, const Eigen::MatrixXd& free_step,
                     SdmMonodromy& out) const {
  const Eigen::Index n = a0_.rows();
  const double dt = toothPeriodS(spindle_rev_per_s) / steps_;
  out.reset(c_, steps_);
  out.setFreeStep(free_step);
  Eigen::MatrixXd aug = Eigen::MatrixXd::Zero(n + 4, n + 4);
  aug.block(n, n + 2, 2, 2).setIdentity();
  Eigen::MatrixXd e(n + 4, n + 4);
  for (int i = 0; i < steps_; ++i) {
    if (!in_cut_[static_cast<size_t>(i)]) continue;
    const Eigen::Matrix<double, Eigen::Dynamic, 2> r = depth_m * p_ * h_[static_cast<size_t>(i)];
    aug.topLeftCorner(n, n) = (a0_ + r * c_) * dt;
    aug.block(0, n, n, 2) = -r * dt;
    e = aug.exp();
    const SdmMonodromy::StepInput e13 = e.block(0, n + 2, n, 2);
    out.setCutStep(i, e.topLeftCorner(n, n), e.block(0, n, n, 2) - e13, e13);
  }
}

}  // namespace mx
