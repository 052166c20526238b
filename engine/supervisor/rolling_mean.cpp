#include "supervisor/rolling_mean.h"

namespace mx {

void RollingMean::push(double value) {
  values_.push_back(value);
  sum_ += value;
  if (values_.size() > window_) {
    sum_ -= values_.front();
    values_.pop_front();
  }
}

}  // namespace mx
