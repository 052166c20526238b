#pragma once
// What every fuzz target shares. A parser may refuse any input with its documented error; what it
// accepts must keep its promises (finite numbers, ranges, an exact round trip through its writer).
// A broken promise is reported and aborts, so that libFuzzer and the replay driver keep the input.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace mx::fuzz {

[[noreturn]] inline void brokenPromise(const char* what) {
  std::fprintf(stderr, "fuzz: broken promise: %s\n", what);
  std::fflush(stderr);
  std::abort();
}

inline void require(bool promiseKept, const char* what) {
  if (!promiseKept) brokenPromise(what);
}

inline void requireFinite(double value, const char* what) {
  require(std::isfinite(value), what);
}

inline std::string_view bytesOf(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A small deterministic number stream from the input's bytes (FNV-1a, then xorshift): the signal
// values and edits a target derives from its input, so that a finding replays from the input alone.
class InputNumbers {
 public:
  explicit InputNumbers(std::string_view bytes) {
    for (const char c : bytes) state_ = (state_ ^ static_cast<std::uint8_t>(c)) * 1099511628211ull;
  }
  std::uint64_t next() {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 7;
    state_ ^= state_ << 17;
    return state_;
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_ = 14695981039346656037ull;
};

}  // namespace mx::fuzz
