#pragma once
// Cutter rotation under sinusoidal spindle speed variation (2006, eq. 12):
//   N(t) = N0 (1 + a sin(2 pi f t)),  theta(t) = 2 pi N0 [t + a (1 - cos(2 pi f t)) / (2 pi f)],
// and the time-varying tooth delay tau(t): theta(t) - theta(t - tau) = 2 pi / n_t.
#include "simulation/simulation_types.h"

namespace mx {

class SpindleKinematics {
 public:
  SpindleKinematics(double nominal_rev_per_s, const SpindleSpeedVariation& ssv, int teeth);

  bool constantSpeed() const { return a_ == 0.0 || f_ == 0.0; }
  double speedRevPerS(double t) const;                 // N(t)
  double angleRad(double t) const;                     // theta(t), theta(0) = 0
  double angleAdvanceRad(double t, double tau) const;  // theta(t) - theta(t - tau), without cancellation
  double pitchRad() const { return pitch_; }
  double nominalToothPeriodS() const { return 1.0 / (n0_ * teeth_); }
  double maxToothDelayS() const;  // pitch / (2 pi N0 (1 - |a|))
  double amplitudeRatio() const { return constantSpeed() ? 0.0 : a_; }

  // tau(t) by safeguarded Newton on g(tau) = theta(t) - theta(t - tau) - pitch, g' = 2 pi N(t - tau) > 0.
  double toothDelayS(double t, double guess) const { return angleDelayS(t, pitch_, guess); }
  double toothDelayS(double t) const { return toothDelayS(t, nominalToothPeriodS()); }
  // The same for any angle: theta(t) - theta(t - tau) = angle (k pitches for the k-th previous tooth).
  double angleDelayS(double t, double angle_rad, double guess) const;

 private:
  double n0_;
  double a_;
  double f_;
  int teeth_;
  double pitch_;
};

}  // namespace mx
