#include "modal_fit/lsfd.h"

#include <Eigen/Dense>
#include <numbers>

#include "modal_fit/modal_pole.h"

namespace mx {

LsfdFit fitResidues(const FrfBand& band, const std::vector<std::complex<double>>& poles) {
  const auto rows = static_cast<Eigen::Index>(band.size());
  const auto modes = static_cast<Eigen::Index>(poles.size());
  const Eigen::Index columns = 2 * modes + 4;
  const double h_scale = band.rmsMagnitude() > 0.0 ? band.rmsMagnitude() : 1.0;
  const double w_low = 2.0 * std::numbers::pi * band.frequency_hz.front();
  // Complex basis of each real unknown; real and imaginary parts stacked below.
  Eigen::MatrixXcd basis(rows, columns);
  Eigen::VectorXcd h(rows);
  const std::complex<double> i{0.0, 1.0};
  for (Eigen::Index k = 0; k < rows; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    const std::complex<double> s{0.0, 2.0 * std::numbers::pi * band.frequency_hz[ku]};
    for (Eigen::Index r = 0; r < modes; ++r) {
      const auto lambda = poles[static_cast<std::size_t>(r)];
      const auto p = 1.0 / (s - lambda), q = 1.0 / (s - std::conj(lambda));
      basis(k, 2 * r) = p + q;            // Re A_r
      basis(k, 2 * r + 1) = i * (p - q);  // Im A_r
    }
    const auto lower = w_low * w_low / (s * s);  // LR in units of h_scale w_low^2
    basis(k, 2 * modes) = lower;
    basis(k, 2 * modes + 1) = i * lower;
    basis(k, 2 * modes + 2) = 1.0;
    basis(k, 2 * modes + 3) = i;
    h(k) = band.h_m_per_n[ku] / h_scale;
  }
  Eigen::MatrixXd a(2 * rows, columns);
  a << basis.real(), basis.imag();
  Eigen::VectorXd b(2 * rows);
  b << h.real(), h.imag();
  const Eigen::VectorXd column_norms = a.colwise().norm().transpose().cwiseMax(1e-300);
  const Eigen::VectorXd x =
      (a * column_norms.cwiseInverse().asDiagonal()).colPivHouseholderQr().solve(b).cwiseQuotient(column_norms);
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
