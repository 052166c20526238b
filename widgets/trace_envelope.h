#pragma once
// Min/max envelope of a long sampled trace for plotting: [t0, t1] is split into `columns` equal
// buckets (one per pixel column) and each bucket that holds a sample gives the least and the greatest
// of its values. A band between the two draws a dense oscillation as its extent instead of a solid
// block of zigzags, with 2 points per column whatever the number of samples, and the extremes of the
// samples in [t0, t1] are exactly the extremes of the envelope.
#include <span>
#include <vector>

namespace mx::widgets {

struct TraceEnvelope {
  // One entry per non-empty bucket, in time order. t is the middle of the bucket's first and last
  // sample times (the first bucket at its first sample, the last at its last: the band spans the data).
  std::vector<double> t, lower, upper;
};

// `time` ascending, `value` as long (the shorter length counts). Samples outside [t0, t1] and
// non-finite values are skipped. Empty for columns < 1 or t1 <= t0.
TraceEnvelope traceEnvelope(std::span<const double> time, std::span<const double> value, double t0, double t1,
                            int columns);

// The number of samples of ascending `time` in [t0, t1].
std::size_t samplesIn(std::span<const double> time, double t0, double t1);

}  // namespace mx::widgets
