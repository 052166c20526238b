#pragma once
// The project's "sdnrp" section (Cus & Zuperl's surface-roughness control loop) in engine
// form; shop units in the file. Every key is optional:
//   "sdnrp": {
//     "ra_um": 0.81,                          desired Ra [um], 0.25..2.5 (default of --ra)
//     "seconds": 15,                          simulated time [s], (0, 600]
//     "disturbance": {"enabled": true, "seed": 2008, "sigma_N": 3, "hold_ms": 10},
//     "initial": {"feed_mm_min": 430.41, "speed_rpm": 1571},   initial cutting conditions
//     "drives": {"feed_natural_frequency_rad_s": 30, "feed_damping": 0.7, "spindle_time_constant_s": 0.3},
//     "integral_rate_per_s": 2                the feed loop's pole (lambda)
//   }
// The section is typed in document/process_sections.h and range-checked when the project is loaded;
// this applies the defaults and converts to SI.
#include "document/project.h"
#include "sdnrp/sdnrp_simulator.h"

namespace mx::app {

SdnrpSettings sdnrpSettingsFrom(const SdnrpSection& section);
// The project's sdnrp section, or the defaults when it has none.
SdnrpSettings sdnrpSettingsFromProject(const Project& project);

}  // namespace mx::app
