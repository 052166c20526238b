#include "control/model_based_force_controller.h"

#include <algorithm>
#include <cmath>

#include "core/invalid_input.h"

namespace mx {
namespace {

void requirePositive(const char* field, double v, const char* unit) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw InvalidInput(std::string("model-based force controller: ") + field + " = " + std::to_string(v) + " " + unit +
                       ": must be > 0 and finite");
}

}  // namespace

ModelBasedForceController::ModelBasedForceController(ModelBasedForceSettings s) : settings_(s) {
  requirePositive("K", s.model.K_N, "N");
  requirePositive("depth_exponent", s.model.depth_exponent, "");
  requirePositive("feed_exponent", s.model.feed_exponent, "");
  requirePositive("length_unit", s.model.length_unit_m, "m");
  requirePositive("reference_force", s.reference_force_N, "N");
  requirePositive("max_feed_rate", s.max_feed_rate_m_per_s, "m/s");
  requirePositive("max_feed_per_tooth", s.max_feed_per_tooth_m, "m");
  if (s.teeth < 1)
    throw InvalidInput("model-based force controller: teeth = " + std::to_string(s.teeth) + ": must be >= 1");
}

double ModelBasedForceController::force(double d, double f) const {
  if (!(d > 0.0) || !(f > 0.0)) return 0.0;
  const auto& m = settings_.model;
  return m.K_N * std::pow(d / m.length_unit_m, m.depth_exponent) * std::pow(f / m.length_unit_m, m.feed_exponent);
}

double ModelBasedForceController::feedPerToothForForce(double d, double F) const {
  const auto& m = settings_.model;
  if (!(F > 0.0)) return 0.0;
  if (!(d > 0.0)) return std::numeric_limits<double>::infinity();
  const double depth_factor = m.K_N * std::pow(d / m.length_unit_m, m.depth_exponent);
  if (!(depth_factor > 0.0)) return std::numeric_limits<double>::infinity();  // d underflows to 0
  const double f = m.length_unit_m * std::pow(F / depth_factor, 1.0 / m.feed_exponent);
  return std::isfinite(f) ? f : std::numeric_limits<double>::infinity();
}

ForceControlDecision ModelBasedForceController::feed(double d, double N) const {
  return feed(d, N, settings_.reference_force_N);
}

ForceControlDecision ModelBasedForceController::feed(double d, double N, double F_ref) const {
  requirePositive("spindle_speed", N, "rev/s");
  requirePositive("reference_force", F_ref, "N");
  if (!std::isfinite(d))
    throw InvalidInput("model-based force controller: depth = " + std::to_string(d) + " m: must be finite");
  const double per_rev = settings_.teeth * N;  // feed rate per unit feed per tooth
  ForceControlDecision out;
  const double f_force = feedPerToothForForce(d, F_ref);
  const double f_drive = settings_.max_feed_rate_m_per_s / per_rev;
  double f = f_force;
  out.limit = FeedLimit::Force;
  if (settings_.max_feed_per_tooth_m < f) f = settings_.max_feed_per_tooth_m, out.limit = FeedLimit::FeedPerTooth;
  if (f_drive < f) f = f_drive, out.limit = FeedLimit::FeedDrive;
  out.feed_per_tooth_m = f;
  out.feed_rate_m_per_s = std::min(f * per_rev, settings_.max_feed_rate_m_per_s);
  out.predicted_force_N = force(d, f);
  return out;
}

std::string ModelBasedForceController::limitName(FeedLimit l) {
  switch (l) {
    case FeedLimit::Force:
      return "force limit";
    case FeedLimit::FeedDrive:
      return "feed-drive max";
    case FeedLimit::FeedPerTooth:
      return "feed-per-tooth max";
  }
  return "";
}

}  // namespace mx
