#include "stability/lobe_diagram.h"

#include <cmath>

namespace mx {

std::vector<double> SpeedGrid::values() const {
  std::vector<double> out;
  if (step_rev_per_s <= 0.0 || to_rev_per_s < from_rev_per_s) return out;
  const auto count = static_cast<long>(std::floor((to_rev_per_s - from_rev_per_s) / step_rev_per_s + 1e-9));
  out.reserve(static_cast<size_t>(count) + 1);
  for (long i = 0; i <= count; ++i) out.push_back(from_rev_per_s + static_cast<double>(i) * step_rev_per_s);
  // A range of a whole number of steps ends at `to` itself, not a rounding error off it, so that `to` is
  // inside the lobes computed on the grid (e.g. q* at the expert grid's top speed).
  if (std::abs(out.back() - to_rev_per_s) <= 1e-9 * step_rev_per_s) out.back() = to_rev_per_s;
  return out;
}

namespace {
// A lobe minimum, not root-finding noise: on each side the envelope rises kProminence above the
// candidate before it falls below it again (+inf counts as risen).
constexpr double kProminence = 0.01;
bool isProminent(const std::vector<double>& depth, size_t i) {
  const double c = depth[i], high = c * (1.0 + kProminence);
  auto rises = [&](int step) {
    for (long j = static_cast<long>(i) + step; j >= 0 && j < static_cast<long>(depth.size()); j += step) {
      const double v = depth[static_cast<size_t>(j)];
      if (v < c) return false;
      if (v > high) return true;
    }
    return false;
  };
  return rises(-1) && rises(+1);
}
}  // namespace

std::vector<LobeMinimum> envelopeMinima(const std::vector<double>& speed, const std::vector<double>& depth,
                                        const std::vector<double>& chatter_hz) {
  std::vector<LobeMinimum> out;
  for (size_t i = 1; i + 1 < depth.size(); ++i) {
    const double l = depth[i - 1], c = depth[i], r = depth[i + 1];
    if (!std::isfinite(l) || !std::isfinite(c) || !std::isfinite(r)) continue;
    if (!(c < l && c <= r)) continue;
    if (!isProminent(depth, i)) continue;
    // Parabola through three equally spaced samples: vertex offset and value.
    const double h = speed[i + 1] - speed[i];
    const double curvature = l - 2.0 * c + r;
    double offset = 0.0, value = c;
    if (curvature > 0.0) {
      offset = 0.5 * (l - r) / curvature;
      value = c - 0.25 * (l - r) * offset;
    }
    const double hz = i < chatter_hz.size() ? chatter_hz[i] : 0.0;
    out.push_back({speed[i] + offset * h, value, hz});
  }
  return out;
}

}  // namespace mx
