#include "control/rls_estimator.h"

#include <cmath>
#include <string>

#include "core/invalid_input.h"

namespace mx {

namespace {
[[noreturn]] void bad(const char* field, double value, const char* range) {
  throw InvalidInput(std::string("RLS: ") + field + " = " + std::to_string(value) + ": must be " + range);
}
}  // namespace

void validateRlsSettings(const RlsSettings& s) {
  if (!(s.forgetting_factor > 0.0 && s.forgetting_factor <= 1.0)) bad("lambda", s.forgetting_factor, "in (0, 1]");
  if (!(s.initial_covariance > 0.0) || !std::isfinite(s.initial_covariance))
    bad("P0", s.initial_covariance, "finite and > 0");
  if (!std::isfinite(s.initial_parameter)) bad("theta0", s.initial_parameter, "finite");
  if (!(s.reset_error_fraction > 0.0) || !std::isfinite(s.reset_error_fraction))
    bad("reset_error_fraction", s.reset_error_fraction, "finite and > 0");
  if (!(s.trace_min >= 0.0 && s.trace_min < s.trace_max)) bad("trace_min", s.trace_min, ">= 0 and < trace_max");
}

RlsEstimator::RlsEstimator(int parameters, const RlsSettings& settings) : s_(settings) {
  if (parameters < 1) throw InvalidInput("RLS: parameters = " + std::to_string(parameters) + ": must be >= 1");
  validateRlsSettings(s_);
  theta_ = Eigen::VectorXd::Constant(parameters, s_.initial_parameter);
  P_ = Eigen::MatrixXd::Identity(parameters, parameters) * s_.initial_covariance;
}

void RlsEstimator::resetCovariance() {
  P_.setIdentity();
  P_ *= s_.initial_covariance;
  ++resets_;
}

void RlsEstimator::setTheta(const Eigen::VectorXd& theta) {
  if (theta.size() != theta_.size() || !theta.allFinite())
    throw InvalidInput("RLS: theta has " + std::to_string(theta.size()) + " entries: must have " +
                       std::to_string(theta_.size()) + " finite entries");
  theta_ = theta;
}

double RlsEstimator::update(const Eigen::VectorXd& phi, double y, double reference) {
  if (phi.size() != theta_.size())
    throw InvalidInput("RLS: regressor size = " + std::to_string(phi.size()) + ": must be " +
                       std::to_string(theta_.size()));
  const double error = y - phi.dot(theta_);
  last_reset_ = false;
  if (!std::isfinite(error) || !phi.allFinite()) return error;  // never let a NaN into the estimate
  if (s_.reset == CovarianceReset::ErrorFraction && std::abs(error) > s_.reset_error_fraction * std::abs(reference)) {
    resetCovariance();
    last_reset_ = true;
  } else if (s_.reset == CovarianceReset::Trace) {
    const double tr = P_.trace();
    if (tr < s_.trace_min || tr > s_.trace_max) {
      resetCovariance();
      last_reset_ = true;
    }
  }
  const Eigen::VectorXd Pphi = P_ * phi;
  const double denom = s_.forgetting_factor + phi.dot(Pphi);  // >= lambda > 0 while P is positive semidefinite
  if (!(denom > 0.0) || !std::isfinite(denom)) return error;
  const Eigen::VectorXd L = Pphi / denom;
  theta_ += L * error;
  P_ = (P_ - L * Pphi.transpose()) / s_.forgetting_factor;
  P_ = 0.5 * (P_ + P_.transpose());  // keep it symmetric against round-off
  return error;
}

}  // namespace mx
