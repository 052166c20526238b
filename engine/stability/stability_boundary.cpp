#include "stability/stability_boundary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "core/invalid_input.h"

namespace mx {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// Distance from p to segment ab in the plane.
double segmentDistance(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0.0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}
}  // namespace

StabilityBoundary::StabilityBoundary(const LobeDiagram& diagram, double alpha)
    : speed_(diagram.speed_rev_per_s), depth_(diagram.envelope_depth_m), alpha_(alpha) {
  if (speed_.size() < 2) throw InvalidInput("a stability boundary needs at least two speeds");
  if (!(alpha > 0.0 && alpha <= 1.0)) {
    std::ostringstream msg;
    msg << "alpha = " << alpha << ": must be in (0, 1]";
    throw InvalidInput(msg.str());
  }
  for (double& b : depth_) b *= alpha;
  minima_ = envelopeMinima(speed_, depth_, diagram.envelope_chatter_hz);
}

bool StabilityBoundary::covers(double speed) const {
  return speed >= speed_.front() && speed <= speed_.back();
}

double StabilityBoundary::depthLimit(double speed) const {
  if (!covers(speed)) {
    std::ostringstream msg;
    msg << "spindle speed " << speed * 60.0 << " rpm is outside the computed lobes [" << speed_.front() * 60.0 << ", "
        << speed_.back() * 60.0 << "] rpm";
    throw InvalidInput(msg.str());
  }
  const auto it = std::upper_bound(speed_.begin(), speed_.end(), speed);
  const size_t j = std::min(static_cast<size_t>(it - speed_.begin()), speed_.size() - 1);
  const size_t i = j - 1;
  const double t = (speed - speed_[i]) / (speed_[j] - speed_[i]);
  if (std::isinf(depth_[i]) || std::isinf(depth_[j])) return t < 0.5 ? depth_[i] : depth_[j];
  return depth_[i] + t * (depth_[j] - depth_[i]);
}

bool StabilityBoundary::isStable(double speed, double depth) const {
  return depth < depthLimit(speed);
}

StabilityVerdict StabilityBoundary::verdict(double speed, double depth) const {
  const double limit = depthLimit(speed);
  if (depth < limit) return StabilityVerdict::Stable;
  return depth <= (1.0 + kMarginalBand) * limit / alpha_ ? StabilityVerdict::Marginal : StabilityVerdict::Unstable;
}

const char* verdictKey(StabilityVerdict verdict) {
  switch (verdict) {
    case StabilityVerdict::Stable:
      return "stable";
    case StabilityVerdict::Marginal:
      return "marginal";
    case StabilityVerdict::Unstable:
      break;
  }
  return "unstable";
}

// Nearest speed left of `speed` (not beyond `stop`) where the envelope falls to `depth`.
double StabilityBoundary::crossingLeft(double speed, double depth, double stop) const {
  size_t j = static_cast<size_t>(std::upper_bound(speed_.begin(), speed_.end(), speed) - speed_.begin());
  double right_n = speed, right_b = depthLimit(speed);
  while (j-- > 0 && speed_[j] >= stop) {
    if (depth_[j] <= depth) {
      if (std::isinf(right_b)) return speed_[j];
      return speed_[j] + (right_n - speed_[j]) * (depth - depth_[j]) / (right_b - depth_[j]);
    }
    right_n = speed_[j];
    right_b = depth_[j];
  }
  return stop;
}

double StabilityBoundary::crossingRight(double speed, double depth, double stop) const {
  size_t j = static_cast<size_t>(std::lower_bound(speed_.begin(), speed_.end(), speed) - speed_.begin());
  double left_n = speed, left_b = depthLimit(speed);
  for (; j < speed_.size() && speed_[j] <= stop; ++j) {
    if (depth_[j] <= depth) {
      if (std::isinf(left_b)) return speed_[j];
      return left_n + (speed_[j] - left_n) * (left_b - depth) / (left_b - depth_[j]);
    }
    left_n = speed_[j];
    left_b = depth_[j];
  }
  return stop;
}

double StabilityBoundary::speedSecurity(double speed, double depth) const {
  if (!isStable(speed, depth)) return 0.0;
  const LobeMinimum* left = nullptr;
  const LobeMinimum* right = nullptr;
  for (const LobeMinimum& m : minima_) {
    if (m.speed_rev_per_s <= speed) left = &m;
    if (m.speed_rev_per_s > speed && right == nullptr) right = &m;
  }
  auto side = [&](const LobeMinimum* m, bool is_left) {
    if (m == nullptr) return kInf;
    if (depth <= m->depth_m) return std::abs(speed - m->speed_rev_per_s);
    const double crossing =
        is_left ? crossingLeft(speed, depth, m->speed_rev_per_s) : crossingRight(speed, depth, m->speed_rev_per_s);
    return std::abs(speed - crossing);
  };
  const double d_left = side(left, true);
  const double d_right = side(right, false);
  const double result = std::min(d_left, d_right);
  return std::isfinite(result) ? result : 0.0;
}

double StabilityBoundary::robustness(double speed, double depth) const {
  if (!(depth > 0.0) || !(speed > 0.0))
    throw InvalidInput("ROS needs a positive speed and depth (got N = " + std::to_string(speed) +
                       " rev/s, b = " + std::to_string(depth) + " m)");
  return scaledDistance(speed, depth, {speed, depth});
}

double StabilityBoundary::scaledDistance(double speed, double depth, const NormalisationSpans& spans) const {
  double best = kInf;
  const double px = speed / spans.speed_rev_per_s, py = depth / spans.depth_m;
  for (size_t i = 0; i + 1 < speed_.size(); ++i) {
    if (std::isinf(depth_[i]) || std::isinf(depth_[i + 1])) continue;
    best = std::min(best, segmentDistance(px, py, speed_[i] / spans.speed_rev_per_s, depth_[i] / spans.depth_m,
                                          speed_[i + 1] / spans.speed_rev_per_s, depth_[i + 1] / spans.depth_m));
  }
  if (!std::isfinite(best)) return best;
  return isStable(speed, depth) ? best : -best;
}

}  // namespace mx
