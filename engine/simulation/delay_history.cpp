#include "simulation/delay_history.h"

#include <stdexcept>

namespace mx {

DelayHistory::DelayHistory(double dt_s, std::int64_t max_lookback) : dt_(dt_s) {
  if (!(dt_s > 0.0) || max_lookback < 1) throw std::invalid_argument("DelayHistory: dt must be > 0 and lookback >= 1");
  std::int64_t capacity = 4;
  while (capacity < max_lookback + 4) capacity *= 2;  // power of two: index by mask
  mask_ = capacity - 1;
  buffer_.assign(static_cast<std::size_t>(capacity), AxisSample{});
}

}  // namespace mx
