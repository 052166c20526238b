#include "machining/depth_profile.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/invalid_input.h"

namespace mx {

DepthProfile DepthProfile::fromStockTop(double stock_top_z_m) {
  if (!std::isfinite(stock_top_z_m))
    throw InvalidInput("stock top = " + std::to_string(stock_top_z_m) + " m: must be finite");
  DepthProfile p;
  p.from_z_ = true;
  p.stock_top_m_ = stock_top_z_m;
  return p;
}

DepthProfile DepthProfile::fromSegments(std::vector<DepthSegment> segments) {
  DepthProfile p;
  p.from_z_ = false;
  double s = 0.0;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto& seg = segments[i];
    if (!(seg.length_m > 0.0) || !std::isfinite(seg.length_m))
      throw InvalidInput("depth profile segment " + std::to_string(i) + " length = " + std::to_string(seg.length_m) +
                         " m: must be > 0");
    if (!(seg.depth_m >= 0.0) || !std::isfinite(seg.depth_m))
      throw InvalidInput("depth profile segment " + std::to_string(i) + " depth = " + std::to_string(seg.depth_m) +
                         " m: must be >= 0");
    s += seg.length_m;
    p.ends_.push_back(s);
  }
  p.segments_ = std::move(segments);
  return p;
}

double DepthProfile::depthForMove(const GcodeMotion& m, double s0) const {
  if (!m.isFeedMove()) return 0.0;
  if (from_z_) return std::max(0.0, stock_top_m_ - m.minZ());
  const double s1 = s0 + m.length_m;
  // first segment whose end is beyond s0
  auto it = std::upper_bound(ends_.begin(), ends_.end(), s0);
  double d = 0.0;
  for (auto k = static_cast<std::size_t>(it - ends_.begin()); k < segments_.size(); ++k) {
    const double start = ends_[k] - segments_[k].length_m;
    if (start >= s1 - 1e-12 && m.length_m > 0.0) break;  // touching segments do not count
    d = std::max(d, segments_[k].depth_m);
    if (m.length_m <= 0.0) break;
  }
  return d;
}

std::vector<double> DepthProfile::blockDepths(const GcodeRun& run) const {
  std::vector<double> out(run.motions.size(), 0.0);
  double s = 0.0;
  for (std::size_t i = 0; i < run.motions.size(); ++i) {
    const auto& m = run.motions[i];
    if (!m.isFeedMove()) continue;
    out[i] = depthForMove(m, s);
    s += m.length_m;
  }
  return out;
}

}  // namespace mx
