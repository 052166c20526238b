#pragma once
// Cooperative cancellation and progress reporting for long engine computations.
#include <atomic>
#include <functional>
#include <stdexcept>

namespace mx {

struct JobControl {
  const std::atomic<bool>* cancel = nullptr;  // polled between chunks
  std::function<void(double)> progress;       // fraction done in [0, 1]

  bool cancelled() const { return cancel != nullptr && cancel->load(std::memory_order_relaxed); }
  void report(double fraction) const {
    if (progress) progress(fraction);
  }
};

class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("computation cancelled") {}
};

}  // namespace mx
