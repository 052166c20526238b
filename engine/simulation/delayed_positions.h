#pragma once
// The delayed tool positions r(t - tau_jk) of every pass set j and remembered pass k at a stage instant
// of step n, read from the DelayHistory (index ToothPasses::index): at the fixed delays of a constant
// speed, or at the time-varying delays of spindle speed variation.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "simulation/cutter_edges.h"
#include "simulation/delay_history.h"
#include "simulation/regenerative_force.h"
#include "simulation/spindle_kinematics.h"

namespace mx {

using PastPositions = std::vector<AxisPosition>;

// Constant speed: tau_jk = d_jk dt with d_jk = (delay in tooth periods) m. A whole d (uniform pitch:
// d = k m) reads sample n - d, the Hermite midpoint and other instants Hermite-interpolated; a
// fractional d (variable pitch) is Hermite-interpolated at n + fraction - d.
class FixedDelay {
 public:
  FixedDelay(const ToothPasses& passes, int steps_per_tooth) {
    for (double periods : passes.delay_tooth_periods) {
      const double d = periods * steps_per_tooth;
      const double whole = std::round(d);
      const bool integral = std::abs(d - whole) <= 1e-9 * d;
      delays_.push_back({integral ? static_cast<std::int64_t>(whole) : 0, integral ? 0.0 : d, integral});
    }
    past_.resize(delays_.size());
  }
  const PastPositions& at(const DelayHistory& history, std::int64_t n, double fraction) {
    for (std::size_t k = 0; k < delays_.size(); ++k) {
      const Delay& delay = delays_[k];
      AxisPosition& p = past_[k];
      if (!delay.integral) {
        p = history.interpolate(static_cast<double>(n) + fraction - delay.steps);
        continue;
      }
      const std::int64_t i = n - delay.whole_steps;
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
  struct Delay {
    std::int64_t whole_steps = 0;
    double steps = 0.0;
    bool integral = true;
  };
  std::vector<Delay> delays_;
  PastPositions past_;
};

// Time-varying delay: r(t - tau_jk(t)) by Hermite interpolation, theta(t) - theta(t - tau_jk) = A_jk
// by Newton. The last three instants are cached (the RK4 mid point is used twice, a step's end is the
// next step's start).
class VariableDelay {
 public:
  VariableDelay(const SpindleKinematics& kinematics, double dt, const ToothPasses& passes)
      : kinematics_(kinematics), dt_(dt), periods_(passes.delay_tooth_periods) {
    for (double periods : periods_) guess_.push_back(periods * kinematics.nominalToothPeriodS());
    for (PastPositions& v : values_) v.resize(periods_.size());
    times_.fill(-1.0);
  }
  const PastPositions& at(const DelayHistory& history, std::int64_t n, double fraction) {
    const double t = (static_cast<double>(n) + fraction) * dt_;
    for (std::size_t c = 0; c < times_.size(); ++c)
      if (times_[c] == t) return values_[c];
    next_ = (next_ + 1) % times_.size();
    for (std::size_t k = 0; k < periods_.size(); ++k) {
      guess_[k] = kinematics_.angleDelayS(t, periods_[k] * kinematics_.pitchRad(), guess_[k]);
      values_[next_][k] = history.interpolate((t - guess_[k]) / dt_);
    }
    times_[next_] = t;
    return values_[next_];
  }

 private:
  const SpindleKinematics& kinematics_;
  double dt_;
  std::vector<double> periods_;  // A_jk / (2 pi / n_t)
  std::vector<double> guess_;
  std::array<double, 3> times_{};
  std::array<PastPositions, 3> values_{};
  std::size_t next_ = 0;
};

}  // namespace mx
