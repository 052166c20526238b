#include "machining/adaptive_path_feeds.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/cancellation.h"
#include "core/invalid_input.h"

namespace mx {

std::vector<CutBlock> cuttingBlocks(const GcodeRun& run, const std::vector<double>& depths_m, bool exclude_plunges) {
  std::vector<CutBlock> out;
  for (std::size_t i = 0; i < run.motions.size() && i < depths_m.size(); ++i) {
    const GcodeMotion& m = run.motions[i];
    if (!m.isFeedMove() || !(depths_m[i] > 0.0) || !(m.length_m > 0.0)) continue;
    const bool pure_z = std::hypot(m.end_m[0] - m.start_m[0], m.end_m[1] - m.start_m[1]) < 1e-9;
    if (pure_z && (m.end_m[2] > m.start_m[2] || exclude_plunges)) continue;  // retract, or plunge
    out.push_back({i, m.length_m, depths_m[i]});
  }
  return out;
}

AdaptivePathFeeds::AdaptivePathFeeds(const AdaptiveControlSettings& base, const std::vector<CutBlock>& cuts,
                                     const JobControl& job) {
  if (cuts.empty()) throw InvalidInput("adaptive path control: the program has no cutting feed move (depth > 0)");
  AdaptiveControlSettings s = base;
  s.workpiece.steps.clear();
  double total = 0.0;
  for (const CutBlock& c : cuts) {
    // Consecutive blocks at the same depth are one step of the workpiece.
    if (!s.workpiece.steps.empty() && s.workpiece.steps.back().depth_m == c.depth_m)
      s.workpiece.steps.back().length_m += c.length_m;
    else
      s.workpiece.steps.push_back({c.length_m, c.depth_m, 0.0});
    total += c.length_m;
  }
  // Enough simulated time to cross the path at a tenth of the drive maximum.
  s.max_time_s = std::max(s.max_time_s, 10.0 * total / s.feed_max_m_s + 1.0);
  run_ = simulateAdaptiveForceControl(s, job);

  double start = 0.0;
  std::ostringstream reason;
  reason << "adaptive beta-FROH force control (beta " << s.beta << ", F_r " << s.force_reference_N << " N)";
  const std::vector<ClosedLoopDensePoint>& dense = run_.dense;
  for (const CutBlock& c : cuts) {
    const double end = start + c.length_m;
    FeedDecision d;
    d.reason = reason.str();
    const double t0 = timeAtPosition(start), t1 = timeAtPosition(end);
    if (std::isfinite(t0) && std::isfinite(t1) && t1 > t0) {
      d.feed_m_per_s = c.length_m / (t1 - t0);
    } else {  // the simulation ended before the block (time cap): its last feed
      d.feed_m_per_s = dense.empty() ? 0.0 : dense.back().feed_actual_m_s;
    }
    double peak = 0.0;
    for (const ClosedLoopDensePoint& p : dense)
      if (p.position_m >= start && p.position_m <= end) peak = std::max(peak, p.force_N);
    d.predicted_force_N = peak;
    if (!(d.feed_m_per_s > 0.0)) d.feed_m_per_s = 1e-6;  // never a zero feed word
    decisions_[c.block] = d;
    start = end;
  }
}

double AdaptivePathFeeds::timeAtPosition(double x) const {
  const std::vector<ClosedLoopDensePoint>& d = run_.dense;
  if (d.empty() || x > d.back().position_m) return std::numeric_limits<double>::infinity();
  if (x <= d.front().position_m) return d.front().t;
  // The position is non-decreasing (the feed is >= 0).
  const auto it =
      std::lower_bound(d.begin(), d.end(), x, [](const ClosedLoopDensePoint& p, double v) { return p.position_m < v; });
  const ClosedLoopDensePoint& b = *it;
  const ClosedLoopDensePoint& a = *(it - 1);
  const double span = b.position_m - a.position_m;
  return span > 0.0 ? a.t + (x - a.position_m) / span * (b.t - a.t) : b.t;
}

std::optional<FeedDecision> AdaptivePathFeeds::decisionFor(std::size_t block) const {
  const auto it = decisions_.find(block);
  if (it == decisions_.end()) return std::nullopt;
  return it->second;
}

BlockFeedController adaptiveFeedController(const AdaptivePathFeeds& feeds) {
  return [&feeds](const CutState& s) {
    if (auto d = feeds.decisionFor(s.block)) return *d;
    FeedDecision keep;
    keep.feed_m_per_s = s.programmed_feed_m_per_s;
    keep.reason = "programmed feed (not a cutting block of the adaptive run)";
    return keep;
  };
}

}  // namespace mx
