#include "trace_envelope.h"

#include <algorithm>
#include <cmath>

namespace mx::widgets {

namespace {
// The bucket being filled: its sample times and extremes.
struct Bucket {
  int index = -1;
  double first_t = 0.0, last_t = 0.0, lo = 0.0, hi = 0.0;
};

void closeBucket(TraceEnvelope& out, const Bucket& b) {
  out.t.push_back(0.5 * (b.first_t + b.last_t));
  out.lower.push_back(b.lo);
  out.upper.push_back(b.hi);
}
}  // namespace

std::size_t samplesIn(std::span<const double> time, double t0, double t1) {
  if (!(t1 >= t0)) return 0;
  const auto first = std::lower_bound(time.begin(), time.end(), t0);
  return static_cast<std::size_t>(std::upper_bound(first, time.end(), t1) - first);
}

TraceEnvelope traceEnvelope(std::span<const double> time, std::span<const double> value, double t0, double t1,
                            int columns) {
  TraceEnvelope out;
  if (columns < 1 || !(t1 > t0) || !std::isfinite(t0) || !std::isfinite(t1)) return out;
  const auto end = time.begin() + static_cast<std::ptrdiff_t>(std::min(time.size(), value.size()));
  const double per_column = columns / (t1 - t0);
  Bucket b;
  double first_t = 0.0;
  for (auto it = std::lower_bound(time.begin(), end, t0); it != end && *it <= t1; ++it) {
    const double t = *it, v = value[static_cast<std::size_t>(it - time.begin())];
    if (!std::isfinite(v)) continue;
    const int index = std::min(columns - 1, static_cast<int>((t - t0) * per_column));
    if (index == b.index) {
      b.last_t = t;
      b.lo = std::min(b.lo, v);
      b.hi = std::max(b.hi, v);
      continue;
    }
    if (b.index >= 0)
      closeBucket(out, b);
    else
      first_t = t;
    b = {index, t, t, v, v};
  }
  if (b.index < 0) return out;
  closeBucket(out, b);
  out.t.front() = first_t;  // the band spans the data
  out.t.back() = b.last_t;
  return out;
}

}  // namespace mx::widgets
