#pragma once
// The model-based machining force controller as a dynamic loop (Landers & Ulsoy, SMC I's module L, after
// Landers & Ulsoy 2000): every period T it reads the measured force F and sets the feed so that the force
// follows a first-order response of time constant tau to the reference.
// The static process F = K d^b f^a is linear in logarithms, ln F = ln(K d^b) + a ln f, with the model's
// feed exponent a as its only gain. Integral action on ln f,
//     ln f(k) = ln f(k-1) + (1 - p) / a (ln F_ref - ln F(k)),   p = exp(-T / tau),
// gives ln F(k+1) = p ln F(k) + (1 - p) ln F_ref for any K d^b when the force of a period answers the
// feed of the period before: the closed-loop pole is p, and an error of the model's K or b leaves no
// steady-state error. The model's K and b enter only where the loop restarts (ResetFeed::Model).
// The feed is kept within the feed-drive and feed-per-tooth maxima; the state is clamped with it, so the
// integrator does not wind up while a maximum holds.
#include "control/model_based_force_controller.h"

namespace mx {

enum class ResetFeed {
  Current,  // bumpless: the loop takes over the feed the axis is moving at (the programmed feed)
  Model,    // the model's static feed for the reference at the programmed depth
};

struct ModelBasedForceLoopSettings {
  ModelBasedForceSettings controller;  // model, reference force, teeth, feed maxima
  double period_s = 0.040;             // module L's period (Table 1)
  double time_constant_s = 0.2;        // closed-loop force time constant tau
  ResetFeed reset_feed = ResetFeed::Model;
  double min_feed_fraction = 1e-3;  // lower clamp of the feed, as a fraction of the largest allowed
};

class ModelBasedForceLoop {
 public:
  // InvalidInput naming the field for a period or time constant that is not > 0, a min_feed_fraction
  // outside (0, 1], or what ModelBasedForceController refuses.
  explicit ModelBasedForceLoop(ModelBasedForceLoopSettings settings);

  // Impulse L*: restart at depth d [m] and spindle speed N [rev/s] from the axis's current feed rate.
  void reset(double current_feed_m_per_s, double depth_m, double speed_rev_per_s);
  // One period: the measured force [N] gives the new feed-rate command [m/s]. A force <= 0 (no chip)
  // holds the feed: the logarithm of the process has no information then.
  double update(double measured_force_N, double speed_rev_per_s);

  double feedRate() const { return feed_rate_m_per_s_; }
  double pole() const { return pole_; }  // p = exp(-T / tau)
  const ModelBasedForceLoopSettings& settings() const { return settings_; }

 private:
  double maxFeedRate(double speed_rev_per_s) const;
  double clampFeed(double feed_m_per_s, double speed_rev_per_s) const;

  ModelBasedForceLoopSettings settings_;
  ModelBasedForceController model_;
  double pole_;
  double feed_rate_m_per_s_ = 0.0;
};

std::string resetFeedName(ResetFeed reset);         // "current", "model"
ResetFeed parseResetFeed(const std::string& name);  // InvalidInput naming the value and the choices

}  // namespace mx
