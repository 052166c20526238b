#pragma once
// The project's "control" section (issue 6: adaptive force control under beta-FROH, 2006 paper,
// section 4) in engine form. Shop units in the file, SI in the engine; every error is CliError(2)
// naming the field, the value and the allowed range.
//   "control": {
//     "tool": "C1",                          optional; default the first tool (teeth, diameter)
//     "spindle_rpm": 715,                    N, (0, 1e5]
//     "cutting_pressure_N_mm2": 1200,        K_c; default: the material's K_t
//     "start_angle_deg": 0, "exit_angle_deg": 180,   default from the operation's immersion
//     "drive_time_constant_ms": 0.1,         tau_m (eq. 21)
//     "process_time_constant_ms": 0,         tau_c; 0 = half a tooth period
//     "beta": 0,                             [-1, 1], the default of --beta
//     "force_reference_N": 1200,             F_r; when absent, from the tool's limits (Rule 3):
//     "breakage_force_N": 2000, "safety_factor": 0.6,   min(safety x breakage, P_spindle / (pi D N))
//     "feed_max_mm_s": 30,                   drive maximum (the minimum is 0)
//     "reference_model": {"damping": 0.75, "rise_time_periods": 4},
//     "rls": {"lambda": 1, "P0": 1e5, "theta0": 0.2, "reset": "error" | "trace" | "none",
//             "reset_fraction": 0.05, "trace_min": 1e-6, "trace_max": 1e12},
//     "workpiece": [{"length_mm": 5.87, "depth_mm": 2}, ...]   default: the paper's figure 7
//   }
#include <QJsonObject>
#include <QString>

#include "control/closed_loop.h"
#include "control/force_reference.h"
#include "project/project.h"

namespace mx::app {

struct ControlRequest {
  QString tool;
  AdaptiveControlSettings settings;
  ForceReference reference;  // how F_r was chosen ("project" when given explicitly)
};

ControlRequest controlRequestFromProject(const Project& project);

// Back to the file's form (the GUI's editors write the section with it).
QJsonObject controlSectionJson(const ControlRequest& request, const QJsonObject& previous);

}  // namespace mx::app
