#pragma once
// The delayed tool positions r(t - tau_k) of the K remembered passes at a stage instant of step n,
// read from the DelayHistory: at a fixed delay tau_k = k T, or at the time-varying delay of spindle
// speed variation.
#include <array>
#include <cstddef>
#include <cstdint>

#include "simulation/delay_history.h"
#include "simulation/regenerative_force.h"
#include "simulation/spindle_kinematics.h"

namespace mx {

using PastPositions = std::array<AxisPosition, kMaxRegenerativePasses>;

// Constant speed: tau_k = k T = k m dt, so r(t_n - kT) is sample n - k m, the mid-step value is the
// Hermite midpoint, and other sub-step instants are Hermite-interpolated.
class FixedDelay {
 public:
  FixedDelay(int steps_per_tooth, int passes) : m_(steps_per_tooth), passes_(passes) {}
  const PastPositions& at(const DelayHistory& history, std::int64_t n, double fraction) {
    for (int k = 0; k < passes_; ++k) {
      const std::int64_t i = n - (k + 1) * m_;
      AxisPosition& p = past_[static_cast<std::size_t>(k)];
      if (fraction == 0.0)
        p = history.position(i);
      else if (fraction == 0.5)
        p = history.midpoint(i);
      else if (fraction == 1.0)
        p = history.position(i + 1);
      else
        p = history.interpolate(static_cast<double>(i) + fraction);
    }
    return past_;
  }

 private:
  std::int64_t m_;
  int passes_;
  PastPositions past_{};
};

// Time-varying delay: r(t - tau_k(t)) by Hermite interpolation, theta(t) - theta(t - tau_k) = k 2 pi / n_t
// by Newton. The last three instants are cached (the RK4 mid point is used twice, a step's end is the
// next step's start).
class VariableDelay {
 public:
  VariableDelay(const SpindleKinematics& kinematics, double dt, int passes)
      : kinematics_(kinematics), dt_(dt), passes_(passes) {
    for (int k = 0; k < passes; ++k) guess_[static_cast<std::size_t>(k)] = (k + 1) * kinematics.nominalToothPeriodS();
    times_.fill(-1.0);
  }
  const PastPositions& at(const DelayHistory& history, std::int64_t n, double fraction) {
    const double t = (static_cast<double>(n) + fraction) * dt_;
    for (std::size_t c = 0; c < times_.size(); ++c)
      if (times_[c] == t) return values_[c];
    next_ = (next_ + 1) % times_.size();
    for (int k = 0; k < passes_; ++k) {
      const auto K = static_cast<std::size_t>(k);
      guess_[K] = kinematics_.angleDelayS(t, (k + 1) * kinematics_.pitchRad(), guess_[K]);
      values_[next_][K] = history.interpolate((t - guess_[K]) / dt_);
    }
    times_[next_] = t;
    return values_[next_];
  }

 private:
  const SpindleKinematics& kinematics_;
  double dt_;
  int passes_;
  std::array<double, kMaxRegenerativePasses> guess_{};
  std::array<double, 3> times_{};
  std::array<PastPositions, 3> values_{};
  std::size_t next_ = 0;
};

}  // namespace mx
