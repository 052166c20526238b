#include "modal_fit/nlls_refinement.h"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <unsupported/Eigen/NonLinearOptimization>

namespace mx {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Parameters scaled to ~1 at the start: per mode (w / w0, zeta / zeta0, c / c0), then Re, Im of LR and
// UR in units of h_scale w_low^2 and h_scale. Residuals: Re, Im of (H_fit - H) / h_scale.
struct ReceptanceResidual {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  const FrfBand& band;
  const FittedModel& start;
  const JobControl& job;
  double h_scale;
  double lower_unit;

  int modes() const { return static_cast<int>(start.modes.size()); }
  int inputs() const { return 3 * modes() + 4; }
  int values() const { return 2 * static_cast<int>(band.size()); }

  FittedModel model(const Eigen::VectorXd& x) const {
    FittedModel m{start.modes, {}};
    for (int r = 0; r < modes(); ++r) {
      Mode& mode = m.modes[static_cast<std::size_t>(r)];
      mode.natural_frequency_hz *= x(3 * r);
      mode.damping_ratio *= x(3 * r + 1);
      mode.stiffness_n_per_m /= x(3 * r + 2);
    }
    const int j = 3 * modes();
    m.residuals.lower = std::complex<double>(x(j), x(j + 1)) * lower_unit;
    m.residuals.upper = std::complex<double>(x(j + 2), x(j + 3)) * h_scale;
    return m;
  }

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& fvec) const {
    if (job.cancelled()) return -1;
    const FittedModel m = model(x);
    const auto n = static_cast<Eigen::Index>(band.size());
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto ku = static_cast<std::size_t>(k);
      const auto e = (fittedReceptance(m, band.frequency_hz[ku]) - band.h_m_per_n[ku]) / h_scale;
      fvec(k) = e.real();
      fvec(n + k) = e.imag();
    }
    return 0;
  }

  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& fjac) const {
    if (job.cancelled()) return -1;
    const FittedModel m = model(x);
    const auto n = static_cast<Eigen::Index>(band.size());
    const int j = 3 * modes();
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto ku = static_cast<std::size_t>(k);
      const std::complex<double> s{0.0, kTwoPi * band.frequency_hz[ku]};
      auto put = [&](int column, std::complex<double> value) {
        fjac(k, column) = value.real() / h_scale;
        fjac(n + k, column) = value.imag() / h_scale;
      };
      for (int r = 0; r < modes(); ++r) {
        const Mode& mode = m.modes[static_cast<std::size_t>(r)];
        const Mode& mode0 = start.modes[static_cast<std::size_t>(r)];
        const double w = mode.angularFrequency(), zeta = mode.damping_ratio, c = 1.0 / mode.stiffness_n_per_m;
        const auto d = s * s + 2.0 * zeta * w * s + w * w;
        const auto d2 = d * d;
        put(3 * r, mode0.angularFrequency() * 2.0 * w * c * s * (s + zeta * w) / d2);
        put(3 * r + 1, mode0.damping_ratio * (-2.0 * w * w * w * c * s / d2));
        put(3 * r + 2, (w * w / d) / mode0.stiffness_n_per_m);
      }
      const auto lower = lower_unit / (s * s);
      put(j, lower);
      put(j + 1, std::complex<double>(0.0, 1.0) * lower);
      put(j + 2, h_scale);
      put(j + 3, std::complex<double>(0.0, h_scale));
    }
    return 0;
  }
};

bool physical(const FittedModel& model) {
  for (const Mode& m : model.modes)
    if (!(m.natural_frequency_hz > 0.0 && m.damping_ratio > 0.0 && m.damping_ratio < 1.0 && m.stiffness_n_per_m > 0.0 &&
          std::isfinite(m.stiffness_n_per_m)))
      return false;
  return true;
}

}  // namespace

FittedModel refineModel(const FrfBand& band, const FittedModel& start, const JobControl& job) {
  if (start.modes.empty() || !physical(start) || band.size() < 2) return start;
  const double h_scale = band.rmsMagnitude() > 0.0 ? band.rmsMagnitude() : 1.0;
  const double w_low = kTwoPi * band.frequency_hz.front();
  ReceptanceResidual residual{band, start, job, h_scale, h_scale * w_low * w_low};
  if (residual.values() < residual.inputs()) return start;
  Eigen::VectorXd x = Eigen::VectorXd::Ones(residual.inputs());
  const int j = 3 * residual.modes();
  x(j) = start.residuals.lower.real() / residual.lower_unit;
  x(j + 1) = start.residuals.lower.imag() / residual.lower_unit;
  x(j + 2) = start.residuals.upper.real() / h_scale;
  x(j + 3) = start.residuals.upper.imag() / h_scale;
  Eigen::VectorXd f0(residual.values());
  residual(x, f0);
  Eigen::LevenbergMarquardt<ReceptanceResidual> lm(residual);
  lm.parameters.maxfev = 100 * (residual.inputs() + 1);
  lm.parameters.xtol = 1e-12;
  lm.parameters.ftol = 1e-12;
  const auto status = lm.minimize(x);
  if (status == Eigen::LevenbergMarquardtSpace::UserAsked ||
      status == Eigen::LevenbergMarquardtSpace::ImproperInputParameters)
    return start;
  FittedModel refined = residual.model(x);
  Eigen::VectorXd f1(residual.values());
  residual(x, f1);
  if (!physical(refined) || !(f1.squaredNorm() <= f0.squaredNorm())) return start;
  return refined;
}

}  // namespace mx
