#include "stability/sdm_model.h"

#include <algorithm>
#include <array>
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
  void add(const TrigIntegrals& o) {
    s2 += o.s2;
    sc += o.sc;
    c2 += o.c2;
  }
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

// Second antiderivatives of the integrands s^2, sc, c^2 clipped to the cut window, for the exact
// average over the helix lag: with P(x) = integral_0^x g f and Q(x) = integral_0^x P,
//   (1 / L) integral_0^L integral_A^B g f(phi - psi) dphi dpsi = (Q(B) - Q(B - L) - Q(A) + Q(A - L)) / L.
// P grows by P_rev per revolution, so for x = 2 pi k + y, 0 <= y < 2 pi:
//   Q(x) = k Q0(2 pi) + pi P_rev k (k - 1) + k P_rev y + Q0(y),  Q0 = Q on [0, 2 pi).
class ClippedTrigPrimitives {
 public:
  explicit ClippedTrigPrimitives(const Immersion& im)
      : entry_(std::clamp(im.entry_rad, 0.0, kTwoPi)), exit_(std::clamp(im.exit_rad, entry_, kTwoPi)) {
    f_entry_ = first(entry_);
    g_entry_ = second(entry_);
    p_rev_ = diff(first(exit_), f_entry_);
    q_exit_ = inWindow(exit_);
    q_rev_ = add(q_exit_, scale(p_rev_, kTwoPi - exit_));
  }

  // The double integral above, as TrigIntegrals summed over [A, A + len] and averaged over the lag.
  TrigIntegrals laggedStep(double a, double len, double lag) const {
    a -= kTwoPi * std::floor(a / kTwoPi);  // second differences ignore the linear growth per revolution
    const double b = a + len;
    const Vec d = add(diff(q(b), q(b - lag)), diff(q(a - lag), q(a)));
    return {d[0] / lag, d[1] / lag, d[2] / lag};
  }

 private:
  using Vec = std::array<double, 3>;  // s^2, sc, c^2
  static Vec add(const Vec& u, const Vec& v) { return {u[0] + v[0], u[1] + v[1], u[2] + v[2]}; }
  static Vec diff(const Vec& u, const Vec& v) { return {u[0] - v[0], u[1] - v[1], u[2] - v[2]}; }
  static Vec scale(const Vec& u, double c) { return {u[0] * c, u[1] * c, u[2] * c}; }
  static Vec first(double y) {
    const double s2 = std::sin(2.0 * y), c2 = std::cos(2.0 * y);
    return {0.5 * y - 0.25 * s2, 0.25 * (1.0 - c2), 0.5 * y + 0.25 * s2};
  }
  static Vec second(double y) {
    const double s2 = std::sin(2.0 * y), c2 = std::cos(2.0 * y);
    return {0.25 * y * y + 0.125 * c2, 0.25 * y - 0.125 * s2, 0.25 * y * y - 0.125 * c2};
  }
  Vec q0(double y) const {
    if (y <= entry_) return {0.0, 0.0, 0.0};  // Q0 on [0, entry] (P0 = 0 there)
    if (y >= exit_) return add(q_exit_, scale(p_rev_, y - exit_));
    return inWindow(y);
  }
  Vec inWindow(double y) const { return diff(diff(second(y), g_entry_), scale(f_entry_, y - entry_)); }
  Vec q(double x) const {
    const double k = std::floor(x / kTwoPi), y = x - kTwoPi * k;
    return add(add(scale(q_rev_, k), scale(p_rev_, std::numbers::pi * k * (k - 1.0) + k * y)), q0(y));
  }

  double entry_, exit_;
  Vec f_entry_{}, g_entry_{}, p_rev_{}, q_exit_{}, q_rev_{};
};

// Below this lag [rad] the exact average loses digits to cancellation; one slice at the mean lag is
// then exact to O(lag^2) < 1e-7.
constexpr double kSmallestExactLagRad = 1e-3;

// A delay this close to a whole number of steps uses the unshifted stencil (equal pitches give exactly
// the uniform discretisation).
constexpr double kWholeStepTolerance = 1e-6;

// a_jk of the Lagrange basis l_j(s) = sum_k a_jk s^k through the nodes s_j = j - back - shift, j = 0 .. p.
Eigen::MatrixXd lagrangeMonomials(int p, int back, double shift) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(p + 1, p + 1);
  for (int j = 0; j <= p; ++j) {
    Eigen::VectorXd poly = Eigen::VectorXd::Zero(p + 1);  // coefficients by power, built factor by factor
    poly[0] = 1.0;
    int degree = 0;
    for (int l = 0; l <= p; ++l) {
      if (l == j) continue;
      const double node = l - back - shift, scale = 1.0 / (j - l);
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

namespace {

// H (eq. in sdm_model.h) from the integrals over a step of angle dphi.
Eigen::Matrix2d coefficientOf(const TrigIntegrals& t, double kt, double kr, double dphi) {
  Eigen::Matrix2d h;
  h << -(t.sc + kr * t.s2), -(t.c2 + kr * t.sc), t.s2 - kr * t.sc, t.sc - kr * t.c2;
  return h * (kt / dphi);
}

// N (sdm_model.h) from the same integrals: the step average of n n^T, n = (sin phi, cos phi).
Eigen::Matrix2d normalProjectorOf(const TrigIntegrals& t, double dphi) {
  Eigen::Matrix2d n;
  n << t.s2, t.sc, t.sc, t.c2;
  return n / dphi;
}

bool cuts(const Eigen::Matrix2d& h) {
  return h.cwiseAbs().maxCoeff() > 0.0;
}

// Adds g to the term of the same offset, or appends it (teeth of different delays can share samples).
void addTerm(std::vector<SdmMonodromy::DelayedTerm>& terms, int offset, const SdmMonodromy::StepInput& g) {
  for (SdmMonodromy::DelayedTerm& t : terms) {
    if (t.offset == offset) {
      t.g += g;
      return;
    }
  }
  terms.push_back({offset, g});
}

}  // namespace

SdmModel::SdmModel(const MillingSetup& setup, int steps_per_tooth_period, int delay_order, int helix_slices)
    : setup_(setup),
      steps_per_tooth_(steps_per_tooth_period),
      teeth_per_period_(setup.teethPerPrincipalPeriod()),
      steps_(steps_per_tooth_period * setup.teethPerPrincipalPeriod()),
      order_(delay_order),
      teeth_(setup.teeth),
      helix_slices_(helix_slices) {
  setup.validateGeometry();
  requireDelayOrder(order_, steps_per_tooth_);
  if (helix_slices_ < kExactHelixSlices || helix_slices_ > kMaxHelixSlices)
    throw InvalidInput("helix_slices = " + std::to_string(helix_slices_) + " is outside the allowed range [0, " +
                       std::to_string(kMaxHelixSlices) + "] (0: exact)");
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
  velocity_ = Eigen::MatrixXd::Zero(2, n);
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
    velocity_(dofs[r].axis, i + 1) = w;
    min_decay_rate_ = std::min(min_decay_rate_, mode.decayRate());
  }

  // Teeth grouped by delay: d_j = pitch_j / dphi steps, dphi = mean pitch / m.
  dphi_ = setup.toothPitchRad() / steps_per_tooth_;
  const bool uniform = setup.uniformPitch();
  for (int j = 0; j < teeth_; ++j) {
    double d = uniform ? steps_per_tooth_ : setup.pitchRad(j) / dphi_;
    if (std::abs(d - std::round(d)) < kWholeStepTolerance) d = std::round(d);  // the plain stencil
    auto same = std::find_if(groups_.begin(), groups_.end(),
                             [d](const DelayGroup& g) { return std::abs(g.base - g.shift - d) < 1e-9; });
    if (same == groups_.end()) {
      DelayGroup g;
      g.base = static_cast<int>(std::ceil(d - 1e-9));
      g.shift = std::max(0.0, g.base - d);
      groups_.push_back(g);
      same = std::prev(groups_.end());
    }
    same->tooth_angles.push_back(setup.toothAngleRad(j));
  }
  const int back = historyBack();
  for (DelayGroup& g : groups_) {
    if (g.base + back - order_ < 0)
      throw InvalidInput("a tooth pitch of " + std::to_string(g.base) + " steps is below the " +
                         std::to_string(order_ - back) + " steps the delay interpolation needs; raise the steps");
    g.lagrange = lagrangeMonomials(order_, back, g.shift);
    depth_ = std::max(depth_, g.base + back);
  }

  // Straight-edge H_i: step i spans cutter angles [i dphi, (i + 1) dphi].
  h_.assign(static_cast<size_t>(steps_), Eigen::Matrix2d::Zero());
  in_cut_.assign(static_cast<size_t>(steps_), false);
  for (DelayGroup& g : groups_) {
    g.straight = groupCoefficients(g, 0.0);
    for (int i = 0; i < steps_; ++i) h_[static_cast<size_t>(i)] += g.straight[static_cast<size_t>(i)].h;
  }
  for (int i = 0; i < steps_; ++i) in_cut_[static_cast<size_t>(i)] = cuts(h_[static_cast<size_t>(i)]);
}

std::vector<SdmModel::StepCoefficients> SdmModel::groupCoefficients(const DelayGroup& g, double depth_m) const {
  const double kt = setup_.tangential_coefficient_pa, kr = setup_.radial_ratio;
  const double lag = setup_.helixLagRad(depth_m);
  const bool exact = helix_slices_ == kExactHelixSlices && std::abs(lag) >= kSmallestExactLagRad;
  // Midpoint slices: lag (k + 1/2) L / n; one slice at L / 2 for straight or nearly straight edges.
  const int slices = exact ? 0 : (helix_slices_ == kExactHelixSlices || lag == 0.0 ? 1 : helix_slices_);
  const ClippedTrigPrimitives primitives(setup_.immersion);
  std::vector<StepCoefficients> out(static_cast<size_t>(steps_));
  for (int i = 0; i < steps_; ++i) {
    TrigIntegrals t;
    for (double angle : g.tooth_angles) {
      const double start = i * dphi_ + angle;
      if (exact) {
        t.add(primitives.laggedStep(start, dphi_, lag));
        continue;
      }
      TrigIntegrals sliced;
      for (int k = 0; k < slices; ++k) addInCut(setup_.immersion, start - lag * (k + 0.5) / slices, dphi_, sliced);
      t.add({sliced.s2 / slices, sliced.sc / slices, sliced.c2 / slices});
    }
    // Round-off outside the cut stays zero: a step whose edges all miss the window contributes nothing.
    if ((std::abs(t.s2) + std::abs(t.c2)) <= 1e-12 * dphi_) continue;
    out[static_cast<size_t>(i)] = {coefficientOf(t, kt, kr, dphi_), normalProjectorOf(t, dphi_)};
  }
  return out;
}

std::vector<std::vector<SdmModel::StepCoefficients>> SdmModel::coefficientsAt(double depth_m) const {
  std::vector<std::vector<StepCoefficients>> out;
  const bool straight = setup_.helix_rad == 0.0 || depth_m == 0.0;
  for (const DelayGroup& g : groups_) out.push_back(straight ? g.straight : groupCoefficients(g, depth_m));
  return out;
}

Eigen::MatrixXd SdmModel::freeStep(double spindle_rev_per_s) const {
  const double dt = principalPeriodS(spindle_rev_per_s) / steps_;
  return (a0_ * dt).exp();
}

double SdmModel::freeDecay(double spindle_rev_per_s) const {
  return a0_.rows() == 0 ? 0.0 : std::exp(-min_decay_rate_ * principalPeriodS(spindle_rev_per_s));
}

void SdmModel::build(double spindle_rev_per_s, double depth_m, const Eigen::MatrixXd& free_step,
                     SdmMonodromy& out) const {
  const Eigen::Index n = a0_.rows();
  const int p = order_, back = historyBack();
  const double dt = principalPeriodS(spindle_rev_per_s) / steps_;
  out.reset(c_, steps_, depth_);
  out.setFreeStep(free_step);
  const std::vector<std::vector<StepCoefficients>> h = coefficientsAt(depth_m);
  const double damping = setup_.processDampingPerDepth(spindle_rev_per_s);  // C_i / V
  StepIntegrals integrals(n, p);
  // The step integrals F_k are linear in the input: integrate -b dt P once and right-multiply by each
  // group's H_i (the state matrix takes the sum of all groups).
  const SdmMonodromy::StepInput input = -depth_m * dt * p_;
  const Eigen::MatrixXd free_x = a0_ * dt;
  std::vector<SdmMonodromy::StepInput> moments(static_cast<size_t>(p + 1));  // k! F_k: integral of s^k
  for (int i = 0; i < steps_; ++i) {
    const auto step = static_cast<size_t>(i);
    Eigen::Matrix2d total = Eigen::Matrix2d::Zero(), normal = Eigen::Matrix2d::Zero();
    for (const auto& group : h) {
      total += group[step].h;
      normal += group[step].normal;
    }
    if (!cuts(total)) continue;
    const Eigen::MatrixXd feedback =
        damping > 0.0 ? Eigen::MatrixXd(total * c_ - damping * normal * velocity_) : Eigen::MatrixXd(total * c_);
    integrals.compute(free_x - input * feedback, input);
    double factorial = 1.0;
    for (int k = 0; k <= p; ++k) {
      if (k > 0) factorial *= k;
      moments[static_cast<size_t>(k)] = factorial * integrals.f(k);
    }
    std::vector<SdmMonodromy::DelayedTerm> terms;
    for (size_t gi = 0; gi < groups_.size(); ++gi) {
      const Eigen::Matrix2d& hg = h[gi][step].h;
      if (!cuts(hg)) continue;
      const DelayGroup& g = groups_[gi];
      for (int j = 0; j <= p; ++j) {
        SdmMonodromy::StepInput sum = SdmMonodromy::StepInput::Zero(n, 2);
        for (int k = 0; k <= p; ++k) sum += g.lagrange(j, k) * moments[static_cast<size_t>(k)];
        addTerm(terms, g.base + back - j, sum * hg);
      }
    }
    out.setCutStep(i, integrals.phi(), std::move(terms));
  }
}

}  // namespace mx
