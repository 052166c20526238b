#include "stability/sdm_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>

#include "core/invalid_input.h"

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

// a_jk of the Lagrange basis l_j(s) = sum_k a_jk s^k through the nodes s_j = j - back, j = 0 .. p.
Eigen::MatrixXd lagrangeMonomials(int p, int back) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(p + 1, p + 1);
  for (int j = 0; j <= p; ++j) {
    Eigen::VectorXd poly = Eigen::VectorXd::Zero(p + 1);  // coefficients by power, built factor by factor
    poly[0] = 1.0;
    int degree = 0;
    for (int l = 0; l <= p; ++l) {
      if (l == j) continue;
      const double node = l - back, scale = 1.0 / (j - l);
      for (int k = degree + 1; k >= 0; --k)
        poly[k] = ((k > 0 ? poly[k - 1] : 0.0) - node * (k <= degree ? poly[k] : 0.0)) * scale;
      ++degree;
    }
    a.row(j) = poly.transpose();
  }
  return a;
}

// Phi = e^X and F_k = integral_0^1 e^{X(1 - s)} B s^k / k! ds = sum_j X^j B / (j + k + 1)!, k = 0 .. p
// (Beta integral). With ||X||_1 <= 1 the Taylor sums are cut after kTaylorTerms terms (remainder below
// 1 / 20! = 4e-19 of the leading term); otherwise one exponential of the augmented matrix
// [X B 0 ..; 0 0 I ..; ..; 0 .. 0] (Van Loan 1978), whose blocks are the same F_k.
constexpr int kTaylorTerms = 20;

class StepIntegrals {
 public:
  StepIntegrals(Eigen::Index n, int p) : n_(n), p_(p), f_(static_cast<size_t>(p + 1)) {
    inverse_factorial_.resize(static_cast<size_t>(kTaylorTerms) + static_cast<size_t>(p) + 2);
    double f = 1.0;
    for (size_t j = 0; j < inverse_factorial_.size(); ++j) {
      if (j > 0) f *= static_cast<double>(j);
      inverse_factorial_[j] = 1.0 / f;
    }
    const Eigen::Index size = n + 2 * (p + 1);
    aug_ = Eigen::MatrixXd::Zero(size, size);
    for (int k = 0; k < p; ++k) aug_.block(n + 2 * k, n + 2 * (k + 1), 2, 2).setIdentity();
  }

  void compute(const Eigen::MatrixXd& x, const SdmMonodromy::StepInput& b) {
    if (x.cwiseAbs().colwise().sum().maxCoeff() <= 1.0) {
      taylor(x, b);
      return;
    }
    aug_.topLeftCorner(n_, n_) = x;
    aug_.block(0, n_, n_, 2) = b;
    const Eigen::MatrixXd e = aug_.exp();
    phi_ = e.topLeftCorner(n_, n_);
    for (int k = 0; k <= p_; ++k) f_[static_cast<size_t>(k)] = e.block(0, n_ + 2 * k, n_, 2);
  }
  const Eigen::MatrixXd& phi() const { return phi_; }
  const SdmMonodromy::StepInput& f(int k) const { return f_[static_cast<size_t>(k)]; }

 private:
  void taylor(const Eigen::MatrixXd& x, const SdmMonodromy::StepInput& b) {
    phi_.setIdentity(n_, n_);
    term_.setIdentity(n_, n_);
    column_ = b;  // X^j B
    for (auto& fk : f_) fk.setZero(n_, 2);
    for (int j = 0; j < kTaylorTerms; ++j) {
      for (int k = 0; k <= p_; ++k)
        f_[static_cast<size_t>(k)] += inverse_factorial_[static_cast<size_t>(j) + static_cast<size_t>(k) + 1] * column_;
      column_ = x * column_;
      term_ = x * term_ * (1.0 / (j + 1));
      phi_ += term_;
    }
  }

  Eigen::Index n_;
  int p_;
  std::vector<double> inverse_factorial_;
  Eigen::MatrixXd aug_, phi_, term_;
  std::vector<SdmMonodromy::StepInput> f_;
  SdmMonodromy::StepInput column_;
};

}  // namespace

void SdmModel::requireDelayOrder(int delay_order, int steps_per_period) {
  const int highest = std::min(kMaxSdmDelayOrder, steps_per_period);
  if (delay_order < 1 || delay_order > highest)
    throw InvalidInput("delay_order = " + std::to_string(delay_order) + " is outside the allowed range [1, " +
                       std::to_string(highest) + "]");
}

SdmModel::SdmModel(const MillingSetup& setup, int steps_per_period, int delay_order)
    : steps_(steps_per_period), order_(delay_order), teeth_(setup.teeth) {
  requireDelayOrder(order_, steps_);
  lagrange_ = lagrangeMonomials(order_, historyBack());
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
  const int p = order_;
  const double dt = toothPeriodS(spindle_rev_per_s) / steps_;
  out.reset(c_, steps_, historyBack(), p + 1);
  out.setFreeStep(free_step);
  StepIntegrals integrals(n, p);
  std::vector<SdmMonodromy::StepInput> g(static_cast<size_t>(p + 1));
  for (int i = 0; i < steps_; ++i) {
    if (!in_cut_[static_cast<size_t>(i)]) continue;
    const Eigen::Matrix<double, Eigen::Dynamic, 2> r = depth_m * p_ * h_[static_cast<size_t>(i)];
    integrals.compute((a0_ + r * c_) * dt, -r * dt);
    double factorial = 1.0;
    for (auto& gj : g) gj.setZero(n, 2);
    for (int k = 0; k <= p; ++k) {
      if (k > 0) factorial *= k;
      const SdmMonodromy::StepInput fk = factorial * integrals.f(k);  // the integral of s^k
      for (int j = 0; j <= p; ++j) g[static_cast<size_t>(j)] += lagrange_(j, k) * fk;
    }
    out.setCutStep(i, integrals.phi(), g);
  }
}

}  // namespace mx
