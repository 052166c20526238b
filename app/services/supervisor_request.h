#pragma once
// The project's "supervisor" section (Landers & Ulsoy's supervisory machining control) in
// engine form. Shop units in the file (typed in document/process_sections.h, checked when the project
// is loaded); errors name the field, the value and the range (charts: the JSON path of the element,
// app/document/project_grafcet_io.h).
//   "supervisor": {
//     "tool": "FM50",                        the face mill (radius = diameter / 2, teeth); default first tool
//     "spindle_rpm": 1500, "programmed_feed_mm_s": 10,
//     "part": {"length_mm": 100, "width_mm": 50, "approach_mm": 2},
//     "passes_mm": {"none": [2], "smc1": [1, 1], "smc2": [2]},   the part program per controller
//     "scan_period_ms": 10,                  supervisor scan (not given by the paper)
//     "reference_force_N": 450,              optional; default from the spindle power limit
//     "power_margin": 0.95,                  F_ref keeps the mean power at this fraction of the limit
//     "chatter_threshold_N": 40,             automatic chatter detector (E)
//     "model_controller": {"time_constant_ms": 200, "reset_feed": "current"},   module L's loop
//     "events": [{"t_s": 20, "type": "feed_hold_on"}, {"t_s": 21, "type": "feed_hold_off"},
//                {"t_s": 5, "type": "chatter"}],   timed operator events
//     "charts": {"none": {...}, "smc1": {...}, "smc2": {...}}   Grafcet charts (docs/grafcet.md)
//   }
// Limits: machine.spindle_power_W (the available power at process.spindle_rpm when machine.max_torque_Nm or
// machine.spindle_curve is given), machine.max_feed_mm_s, operation.max_feed_per_tooth_mm.
#include <QString>
#include <QStringList>

#include "document/project.h"
#include "grafcet/grafcet_chart.h"
#include "supervisor/supervision_run.h"

namespace mx::app {

// The signals the supervised run gives the charts (Table 2): a feed hold requested, b contact,
// c chatter signalled by the operator, d chatter detected automatically, e suppression routine
// complete, and F_Y [N].
const std::set<std::string>& supervisionSignals();

struct SupervisorRequest {
  SupervisionScenario scenario;
  GrafcetChart chart;
  QString chart_path;  // "supervisor.charts.smc1"
};

// controller: "none", "smc1" or "smc2" (InputError otherwise: it is the --controller flag).
SupervisorRequest supervisorRequestFrom(const SupervisorSection& section, const Project& project,
                                        const QString& controller);
// The project's supervisor section; ProjectError when it has none.
SupervisorRequest supervisorRequestFromProject(const Project& project, const QString& controller);

QStringList supervisorControllers();  // {"none", "smc1", "smc2"}

}  // namespace mx::app
