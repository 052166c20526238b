#include "simulation/spindle_kinematics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mx {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
}

SpindleKinematics::SpindleKinematics(double nominal_rev_per_s, const SpindleSpeedVariation& ssv, int teeth)
    : n0_(nominal_rev_per_s), a_(ssv.amplitude_ratio), f_(ssv.frequency_hz), teeth_(teeth), pitch_(kTwoPi / teeth) {}

double SpindleKinematics::speedRevPerS(double t) const {
  if (constantSpeed()) return n0_;
  return n0_ * (1.0 + a_ * std::sin(kTwoPi * f_ * t));
}

double SpindleKinematics::angleRad(double t) const {
  if (constantSpeed()) return kTwoPi * n0_ * t;
  return kTwoPi * n0_ * (t + a_ * (1.0 - std::cos(kTwoPi * f_ * t)) / (kTwoPi * f_));
}

double SpindleKinematics::angleAdvanceRad(double t, double tau) const {
  if (constantSpeed()) return kTwoPi * n0_ * tau;
  const double w = kTwoPi * f_;
  return kTwoPi * n0_ * (tau + a_ * (std::cos(w * (t - tau)) - std::cos(w * t)) / w);
}

double SpindleKinematics::maxToothDelayS() const {
  return pitch_ / (kTwoPi * n0_ * (1.0 - std::abs(constantSpeed() ? 0.0 : a_)));
}

double SpindleKinematics::angleDelayS(double t, double angle_rad, double guess) const {
  if (constantSpeed()) return angle_rad / (kTwoPi * n0_);
  // The angle advance over tau grows at a rate between 2 pi N0 (1 -+ |a|): bracket the root.
  double lo = angle_rad / (kTwoPi * n0_ * (1.0 + std::abs(a_)));
  double hi = angle_rad / (kTwoPi * n0_ * (1.0 - std::abs(a_)));
  double tau = std::clamp(guess, lo, hi);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double g = angleAdvanceRad(t, tau) - angle_rad;
    const double newton_step = g / (kTwoPi * speedRevPerS(t - tau));
    if (std::abs(newton_step) <= 1e-15 * tau) return tau - newton_step;
    if (g > 0.0)
      hi = tau;
    else
      lo = tau;
    double next = tau - newton_step;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    tau = next;
    if (hi - lo <= 1e-15 * tau) break;
  }
  return tau;
}

}  // namespace mx
