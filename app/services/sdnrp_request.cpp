#include "services/sdnrp_request.h"

namespace mx::app {

SdnrpSettings sdnrpSettingsFrom(const SdnrpSection& c) {
  SdnrpSettings s;
  s.ra_desired_m = c.ra_um.value_or(0.81) * 1e-6;
  s.duration_s = c.seconds.value_or(15.0);
  const SdnrpDisturbanceSpec d = c.disturbance.value_or(SdnrpDisturbanceSpec{});
  s.disturbance.enabled = d.enabled.value_or(true);
  s.disturbance.seed = static_cast<std::uint64_t>(d.seed.value_or(2008.0));
  s.disturbance.sigma_N = d.sigma_N.value_or(3.0);
  s.disturbance.hold_s = d.hold_ms.value_or(10.0) * 1e-3;
  const SdnrpInitialSpec init = c.initial.value_or(SdnrpInitialSpec{});
  if (init.feed_mm_min) s.initial_feed_m_per_s = *init.feed_mm_min / 60e3;
  if (init.speed_rpm) s.initial_speed_rev_per_s = *init.speed_rpm / 60.0;
  const SdnrpDrivesSpec dr = c.drives.value_or(SdnrpDrivesSpec{});
  s.drives.feed_natural_frequency_rad_s = dr.feed_natural_frequency_rad_s.value_or(30.0);
  s.drives.feed_damping = dr.feed_damping.value_or(0.7);
  s.drives.spindle_time_constant_s = dr.spindle_time_constant_s.value_or(0.3);
  s.integral_rate_per_s = c.integral_rate_per_s.value_or(2.0);
  return s;
}

SdnrpSettings sdnrpSettingsFromProject(const Project& project) {
  return sdnrpSettingsFrom(project.sdnrp.value_or(SdnrpSection{}));
}

}  // namespace mx::app
