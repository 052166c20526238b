#include "cli/sdnrp_request.h"

#include <QJsonObject>
#include <cmath>

#include "cli/cli_support.h"

namespace mx::app {

SdnrpSettings sdnrpSettingsFromProject(const Project& project) {
  const QJsonObject c = project.document.value("sdnrp").toObject();
  SdnrpSettings s;
  s.ra_desired_m = sectionNumber(c, "sdnrp", "ra_um", 0.25, 2.5, "in [0.25, 2.5]", 0.81) * 1e-6;
  s.duration_s = sectionNumber(c, "sdnrp", "seconds", 0.1, 600.0, "in [0.1, 600]", 15.0);
  const QJsonObject d = c.value("disturbance").toObject();
  s.disturbance.enabled = d.value("enabled").toBool(true);
  const double seed = sectionNumber(d, "sdnrp.disturbance", "seed", 0.0, 9.0e15, "an integer in [0, 9e15]", 2008.0);
  if (std::floor(seed) != seed) failField("sdnrp.disturbance.seed", QString::number(seed), "an integer in [0, 9e15]");
  s.disturbance.seed = static_cast<std::uint64_t>(seed);
  s.disturbance.sigma_N = sectionNumber(d, "sdnrp.disturbance", "sigma_N", 0.0, 1e4, "in [0, 1e4]", 3.0);
  s.disturbance.hold_s = sectionNumber(d, "sdnrp.disturbance", "hold_ms", 1.0, 1e4, "in [1, 1e4]", 10.0) * 1e-3;
  const QJsonObject init = c.value("initial").toObject();
  if (init.contains("feed_mm_min"))
    s.initial_feed_m_per_s = sectionNumber(init, "sdnrp.initial", "feed_mm_min", 1e-3, 1e5, "in (0, 1e5]") / 60e3;
  if (init.contains("speed_rpm"))
    s.initial_speed_rev_per_s = sectionNumber(init, "sdnrp.initial", "speed_rpm", 1e-3, 1e5, "in (0, 1e5]") / 60.0;
  const QJsonObject dr = c.value("drives").toObject();
  s.drives.feed_natural_frequency_rad_s =
      sectionNumber(dr, "sdnrp.drives", "feed_natural_frequency_rad_s", 0.1, 1e4, "in [0.1, 1e4]", 30.0);
  s.drives.feed_damping = sectionNumber(dr, "sdnrp.drives", "feed_damping", 0.05, 5.0, "in [0.05, 5]", 0.7);
  s.drives.spindle_time_constant_s =
      sectionNumber(dr, "sdnrp.drives", "spindle_time_constant_s", 1e-4, 100.0, "in [1e-4, 100]", 0.3);
  s.integral_rate_per_s = sectionNumber(c, "sdnrp", "integral_rate_per_s", 1e-3, 100.0, "in [1e-3, 100]", 2.0);
  return s;
}

}  // namespace mx::app
