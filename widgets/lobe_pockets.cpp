#include "lobe_pockets.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mx::widgets {

namespace {

// The lowest envelope value walking from `peak` in `step` (+1 or -1) until the envelope rises above
// the peak or the range ends: the saddle that separates the peak from higher ground. NaN (no limit
// below the lobes' depth cap) is higher ground.
double saddleDepth(const QVector<double>& depth, qsizetype peak, int step) {
  double lowest = depth[peak];
  for (qsizetype j = peak + step; j >= 0 && j < depth.size(); j += step) {
    if (!(depth[j] <= depth[peak])) break;
    lowest = std::min(lowest, depth[j]);
  }
  return lowest;
}

}  // namespace

QVector<StabilityPocket> findStabilityPockets(const QVector<double>& speed_rpm, const QVector<double>& depth_mm,
                                              double min_prominence) {
  QVector<StabilityPocket> pockets;
  const qsizetype n = std::min(speed_rpm.size(), depth_mm.size());
  for (qsizetype i = 1; i + 1 < n; ++i) {
    if (!std::isfinite(depth_mm[i]) || !(depth_mm[i] > depth_mm[i - 1])) continue;
    qsizetype last = i;  // the end of a plateau starting at i
    while (last + 1 < n && depth_mm[last + 1] == depth_mm[i]) ++last;
    if (last + 1 >= n || !(depth_mm[last + 1] < depth_mm[i])) {
      i = last;
      continue;
    }
    const double saddle = std::max(saddleDepth(depth_mm, i, -1), saddleDepth(depth_mm, last, +1));
    if (depth_mm[i] - saddle >= min_prominence * depth_mm[i])
      pockets.push_back({0.5 * (speed_rpm[i] + speed_rpm[last]), depth_mm[i]});
    i = last;
  }
  std::stable_sort(pockets.begin(), pockets.end(),
                   [](const StabilityPocket& a, const StabilityPocket& b) { return a.depth_mm > b.depth_mm; });
  return pockets;
}

double envelopeAt(const QVector<double>& speed_rpm, const QVector<double>& depth_mm, double speed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const qsizetype n = std::min(speed_rpm.size(), depth_mm.size());
  if (n == 0 || !(speed >= speed_rpm.front()) || !(speed <= speed_rpm[n - 1])) return nan;
  const auto end = speed_rpm.begin() + n;
  const qsizetype hi = std::max<qsizetype>(std::lower_bound(speed_rpm.begin(), end, speed) - speed_rpm.begin(), 1);
  if (hi >= n) return depth_mm[n - 1];
  const double x0 = speed_rpm[hi - 1], x1 = speed_rpm[hi];
  if (speed == x1) return depth_mm[hi];  // a sample: its own value, even beside a NaN
  if (speed == x0) return depth_mm[hi - 1];
  const double t = (speed - x0) / (x1 - x0);
  return depth_mm[hi - 1] + t * (depth_mm[hi] - depth_mm[hi - 1]);  // NaN next to a NaN
}

}  // namespace mx::widgets
