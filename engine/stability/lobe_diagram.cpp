#include "stability/lobe_diagram.h"

#include <cmath>

namespace mx {

std::vector<double> SpeedGrid::values() const {
  std::vector<double> out;
  if (step_rev_per_s <= 0.0 || to_rev_per_s < from_rev_per_s) return out;
  const auto count = static_cast<long>(std::floor((to_rev_per_s - from_rev_per_s) / step_rev_per_s + 1e-9));
  out.reserve(static_cast<size_t>(count) + 1);
  for (long i = 0; i <= count; ++i) out.push_back(from_rev_per_s + static_cast<double>(i) * step_rev_per_s);
  return out;
}

std::vector<LobeMinimum> envelopeMinima(const std::vector<double>& speed, const std::vector<double>& depth,
                                        const std::vector<double>& chatter_hz) {
  std::vector<LobeMinimum> out;
  for (size_t i = 1; i + 1 < depth.size(); ++i) {
    const double l = depth[i - 1], c = depth[i], r = depth[i + 1];
    if (!std::isfinite(l) || !std::isfinite(c) || !std::isfinite(r)) continue;
    if (!(c < l && c <= r)) continue;
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
