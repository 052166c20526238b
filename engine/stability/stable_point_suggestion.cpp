#include "stability/stable_point_suggestion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace mx {

namespace {

constexpr int kMaxSmithTlustyK = 1000;

struct Range {
  double lo = 0.0, hi = 0.0;
  bool contains(double n) const { return n >= lo && n <= hi; }
};

bool differs(double n, double current) {
  return std::abs(n - current) > kSameSpeed * current;
}

std::optional<StablePointSuggestion> smithTlusty(const StabilityBoundary& b, double speed, double depth,
                                                 double chatter_hz, int teeth, Range range) {
  std::optional<StablePointSuggestion> best;
  for (int k = 1; k <= kMaxSmithTlustyK; ++k) {
    const double n = chatter_hz / (teeth * static_cast<double>(k));
    if (n < range.lo) break;
    if (!range.contains(n) || !differs(n, speed) || b.verdict(n, depth) != StabilityVerdict::Stable) continue;
    if (!best || std::abs(n - speed) < std::abs(best->speed_rev_per_s - speed))
      best = StablePointSuggestion{StablePointSuggestion::Kind::SmithTlusty, n, depth, k};
  }
  return best;
}

// The samples of the boundary inside the range, as indices.
std::vector<std::size_t> samplesIn(const StabilityBoundary& b, Range range) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < b.speeds().size(); ++i)
    if (range.contains(b.speeds()[i])) out.push_back(i);
  return out;
}

// The peak of the nearest stretch of samples where `depth` is stable (not at the current speed).
std::optional<StablePointSuggestion> nearestStableSpeed(const StabilityBoundary& b, double speed, double depth,
                                                        const std::vector<std::size_t>& samples) {
  const auto& n = b.speeds();
  const auto& lim = b.depths();
  std::optional<std::size_t> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < samples.size();) {
    if (!(depth < lim[samples[s]])) {
      ++s;
      continue;
    }
    std::size_t peak = samples[s];
    double distance = std::numeric_limits<double>::infinity();
    for (; s < samples.size() && depth < lim[samples[s]]; ++s) {
      const std::size_t i = samples[s];
      if (lim[i] > lim[peak]) peak = i;
      distance = std::min(distance, std::abs(n[i] - speed));
    }
    if (differs(n[peak], speed) && distance < best_distance) {
      best_distance = distance;
      best = peak;
    }
  }
  if (!best) return std::nullopt;
  return StablePointSuggestion{StablePointSuggestion::Kind::NearestStableSpeed, n[*best], depth, 0};
}

// The nearest local maximum of alpha b_lim (an end of the range counts when the boundary rises to it).
StablePointSuggestion shallowerDepth(const StabilityBoundary& b, double speed,
                                     const std::vector<std::size_t>& samples) {
  const auto& n = b.speeds();
  const auto& lim = b.depths();
  std::size_t best = samples.front();
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const std::size_t i = samples[s];
    const bool left_lower = s == 0 || lim[samples[s - 1]] <= lim[i];
    const bool right_lower = s + 1 == samples.size() || lim[samples[s + 1]] <= lim[i];
    if (!(left_lower && right_lower)) continue;
    const double distance = std::abs(n[i] - speed);
    if (distance < best_distance || (distance == best_distance && lim[i] > lim[best])) {
      best_distance = distance;
      best = i;
    }
  }
  return {StablePointSuggestion::Kind::ShallowerDepth, n[best], kPocketDepthShare * lim[best], 0};
}

}  // namespace

std::optional<StablePointSuggestion> suggestStablePoint(const StabilityBoundary& boundary, double speed_rev_per_s,
                                                        double depth_m, std::optional<double> chatter_hz, int teeth,
                                                        double min_rev_per_s, double max_rev_per_s) {
  const Range range{std::max(min_rev_per_s, boundary.minSpeed()), std::min(max_rev_per_s, boundary.maxSpeed())};
  if (!(range.lo <= range.hi)) return std::nullopt;
  if (chatter_hz && *chatter_hz > 0.0 && teeth >= 1)
    if (auto s = smithTlusty(boundary, speed_rev_per_s, depth_m, *chatter_hz, teeth, range)) return s;
  const std::vector<std::size_t> samples = samplesIn(boundary, range);
  if (samples.empty()) return std::nullopt;
  if (auto s = nearestStableSpeed(boundary, speed_rev_per_s, depth_m, samples)) return s;
  return shallowerDepth(boundary, speed_rev_per_s, samples);
}

}  // namespace mx
