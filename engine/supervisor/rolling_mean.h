#pragma once
// Mean of the last `window` values pushed, kept as a running sum: each push adds the new value and
// subtracts the one that leaves, so a push costs O(1) whatever the window.
#include <cstddef>
#include <deque>

namespace mx {

class RollingMean {
 public:
  explicit RollingMean(std::size_t window) : window_(window) {}

  void push(double value);
  // Mean of the values held (at most `window`); NaN before the first push. The running sum can
  // drift slightly below zero for non-negative values, so callers clamp where the sign matters.
  double mean() const { return sum_ / static_cast<double>(values_.size()); }
  std::size_t size() const { return values_.size(); }
  std::size_t window() const { return window_; }

 private:
  std::size_t window_;
  std::deque<double> values_;
  double sum_ = 0.0;
};

}  // namespace mx
