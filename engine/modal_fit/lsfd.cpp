#include "modal_fit/lsfd.h"

#include <Eigen/Dense>
#include <numbers>

#include "modal_fit/modal_pole.h"

namespace mx {
namespace {

// Normal equations G x = c with unit-diagonal scaling, by LDLT; by column-pivoting QR when the pivots
// spread beyond 1e-12 (e.g. two poles almost on top of each other).
Eigen::VectorXd solveNormalEquations(const Eigen::MatrixXd& gram, const Eigen::VectorXd& rhs) {
  const Eigen::VectorXd scale = gram.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd g = scale.asDiagonal() * gram * scale.asDiagonal();
  const Eigen::VectorXd c = scale.cwiseProduct(rhs);
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(g);
  const Eigen::VectorXd d = ldlt.vectorD().cwiseAbs();
  if (ldlt.info() == Eigen::Success && d.size() > 0 && d.minCoeff() > 1e-12 * d.maxCoeff())
    return scale.cwiseProduct(ldlt.solve(c));
  return scale.cwiseProduct(g.colPivHouseholderQr().solve(c));
}

}  // namespace

// Each frequency adds the real and imaginary parts of its row of complex basis functions (one per
// real unknown) to the normal equations, G += Re(row^H row), c += Re(row^H h): no N-row matrix.
LsfdFit fitResidues(const FrfBand& band, const std::vector<std::complex<double>>& poles) {
  const auto modes = static_cast<Eigen::Index>(poles.size());
  const Eigen::Index columns = 2 * modes + 4;
  const double h_scale = band.rmsMagnitude() > 0.0 ? band.rmsMagnitude() : 1.0;
  const double w_low = 2.0 * std::numbers::pi * band.frequency_hz.front();
  const std::complex<double> i{0.0, 1.0};
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(columns, columns);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(columns);
  Eigen::VectorXcd row(columns);
  Eigen::VectorXd re(columns), im(columns);
  for (std::size_t k = 0; k < band.size(); ++k) {
    const std::complex<double> s{0.0, 2.0 * std::numbers::pi * band.frequency_hz[k]};
    for (Eigen::Index r = 0; r < modes; ++r) {
      const auto lambda = poles[static_cast<std::size_t>(r)];
      const auto p = 1.0 / (s - lambda), q = 1.0 / (s - std::conj(lambda));
      row(2 * r) = p + q;            // Re A_r
      row(2 * r + 1) = i * (p - q);  // Im A_r
    }
    const auto lower = w_low * w_low / (s * s);  // LR in units of h_scale w_low^2
    row(2 * modes) = lower;
    row(2 * modes + 1) = i * lower;
    row(2 * modes + 2) = 1.0;
    row(2 * modes + 3) = i;
    const std::complex<double> h = band.h_m_per_n[k] / h_scale;
    re = row.real();
    im = row.imag();
    gram.selfadjointView<Eigen::Lower>().rankUpdate(re);
    gram.selfadjointView<Eigen::Lower>().rankUpdate(im);
    rhs += re * h.real() + im * h.imag();
  }
  gram = gram.selfadjointView<Eigen::Lower>();
  const Eigen::VectorXd x = solveNormalEquations(gram, rhs);
  LsfdFit fit;
  for (Eigen::Index r = 0; r < modes; ++r) fit.residues.emplace_back(x(2 * r) * h_scale, x(2 * r + 1) * h_scale);
  const double lower_unit = h_scale * w_low * w_low;
  fit.residuals.lower = {x(2 * modes) * lower_unit, x(2 * modes + 1) * lower_unit};
  fit.residuals.upper = {x(2 * modes + 2) * h_scale, x(2 * modes + 3) * h_scale};
  return fit;
}

FittedModel fittedModel(const std::vector<std::complex<double>>& poles, const LsfdFit& fit) {
  FittedModel model{{}, fit.residuals};
  for (std::size_t r = 0; r < poles.size() && r < fit.residues.size(); ++r)
    model.modes.push_back(modeFromResidue(poles[r], fit.residues[r]));
  return model;
}

}  // namespace mx
