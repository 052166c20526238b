#pragma once
// Test helper: how far one sampled signal is from a reference.
#include <algorithm>
#include <cmath>
#include <vector>

namespace mx::test {

// max |a - b| over the common samples, relative to max |b| (absolute when b is zero).
inline double maxRelativeDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0.0, peak = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
    diff = std::max(diff, std::abs(a[k] - b[k]));
    peak = std::max(peak, std::abs(b[k]));
  }
  return peak > 0.0 ? diff / peak : diff;
}

}  // namespace mx::test
