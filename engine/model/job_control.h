#pragma once
// Cooperative cancellation and progress reporting for long engine computations.
#include <atomic>
#include <functional>
#include <stdexcept>

namespace mx {

struct JobControl {
  const std::atomic<bool>* cancel = nullptr;      // polled between chunks
  std::function<void(double)> progress;           // fraction done in [0, 1]

  bool cancelled() const { return cancel != nullptr && cancel->load(std::memory_order_relaxed); }
  void report(double fraction) const {
    if (progress) progress(fraction);
  }
};

class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("computation cancelled") {}
};

// Thrown for inputs outside a method's domain; the message names the quantity, value and range.
class InvalidInput : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace mx
