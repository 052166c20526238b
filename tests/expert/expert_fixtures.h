#pragma once
// The 2006 example (section 3.D) as expert-system inputs: R1, R2, and the settings of
// projects/rubio2006-tool-selection.mxproj (grid 800-6000 rpm by 1000 rpm, depth b_min/10, feed 0.01 mm).
#include "expert/expert_session.h"
#include "expert/expert_settings.h"
#include "support/fixtures.h"

namespace mx::test {

inline ExpertSettings rubioExpertSettings() {
  ExpertSettings s;
  s.grid.speed_from_rev_per_s = 800.0 / 60.0;
  s.grid.speed_to_rev_per_s = 6000.0 / 60.0;
  s.grid.speed_step_rev_per_s = 1000.0 / 60.0;
  s.grid.depth_divisions = 10;
  s.grid.feed_step_m = 0.01e-3;
  s.limits.spindle_power_w = 745.3;
  s.limits.max_spindle_rev_per_s = 12000.0 / 60.0;
  s.limits.max_feed_per_tooth_m = 0.55e-3;
  s.stability.delta_per_s = 0.05;
  s.stability.alpha = 0.95;
  return s;
}

// The session of R1 and R2 with those settings, built once per test process.
inline const ExpertSession& rubioSession() {
  static const ExpertSession session({rubioR1(), rubioR2()}, rubioExpertSettings());
  return session;
}
// Their indexes in the session.
inline constexpr std::size_t kR1 = 0, kR2 = 1;

}  // namespace mx::test
