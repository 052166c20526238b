#pragma once
// Recursive least squares with forgetting factor (2006 paper, eq. 26):
//   L(k) = P(k-1) phi / (lambda + phi' P(k-1) phi)
//   theta(k) = theta(k-1) + L(k) [y(k) - phi' theta(k-1)]
//   P(k) = (I - L phi') P(k-1) / lambda
// with covariance resetting: P <- P0 I before the update when the a-priori error exceeds a fraction of the
// reference (5 %, Altintas et al. 1990), or when trace(P) leaves [trace_min, trace_max] (Altintas 2000).
#include <Eigen/Core>

namespace mx {

enum class CovarianceReset { None, ErrorFraction, Trace };

struct RlsSettings {
  double forgetting_factor = 1.0;   // lambda in (0, 1]
  double initial_covariance = 1e5;  // P(0) = p0 I
  double initial_parameter = 0.2;   // theta_i(0)
  CovarianceReset reset = CovarianceReset::ErrorFraction;
  double reset_error_fraction = 0.05;  // |e| > fraction * |reference|
  double trace_min = 1e-6;             // Trace rule: reset when trace(P) < trace_min ...
  double trace_max = 1e12;             // ... or > trace_max
};

void validateRlsSettings(const RlsSettings& s);  // InvalidInput naming the field, value and range

class RlsEstimator {
 public:
  RlsEstimator(int parameters, const RlsSettings& settings);
  // One step; `reference` is the magnitude the ErrorFraction rule compares with. Returns the a-priori error.
  double update(const Eigen::VectorXd& phi, double y, double reference = 0.0);
  void resetCovariance();
  void setTheta(const Eigen::VectorXd& theta);

  const Eigen::VectorXd& theta() const { return theta_; }
  const Eigen::MatrixXd& covariance() const { return P_; }
  int resets() const { return resets_; }
  bool lastUpdateReset() const { return last_reset_; }

 private:
  RlsSettings s_;
  Eigen::VectorXd theta_;
  Eigen::MatrixXd P_;
  int resets_ = 0;
  bool last_reset_ = false;
};

}  // namespace mx
