#pragma once
// The monkey's only source of randomness: every choice goes through one seeded std::mt19937_64, so a
// seed names a run.
#include <QtGlobal>
#include <cstddef>
#include <random>
#include <vector>

namespace mx::e2e {

class Dice {
 public:
  explicit Dice(quint64 seed) : engine_(seed) {}

  int below(int n) { return n <= 1 ? 0 : std::uniform_int_distribution<int>(0, n - 1)(engine_); }
  int between(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  bool chance(double p) { return std::uniform_real_distribution<double>(0.0, 1.0)(engine_) < p; }
  template <class T>
  const T& pick(const std::vector<T>& items) {
    return items[static_cast<std::size_t>(below(static_cast<int>(items.size())))];
  }
  // An index drawn with probability proportional to its weight.
  std::size_t weighted(const std::vector<double>& weights) {
    return std::discrete_distribution<std::size_t>(weights.begin(), weights.end())(engine_);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace mx::e2e
