#include "services/supervisor_request.h"

#include <algorithm>

#include "core/invalid_input.h"
#include "document/project_grafcet_io.h"
#include "document/project_rules.h"
#include "document/shortened_text.h"
#include "services/service_errors.h"

namespace mx::app {

const std::set<std::string>& supervisionSignals() {
  static const std::set<std::string> names{"a", "b", "c", "d", "e", "F_Y"};
  return names;
}

QStringList supervisorControllers() {
  return {"none", "smc1", "smc2"};
}

SupervisorRequest supervisorRequestFrom(const SupervisorSection& s, const Project& project, const QString& controller) {
  if (!supervisorControllers().contains(controller))
    throw InputError(QString("--controller = %1: must be one of none, smc1, smc2").arg(quoted(controller)));
  SupervisorRequest r;
  SupervisionScenario& sc = r.scenario;
  sc.controller = parseController(controller.toStdString());

  const QString tool_id = s.tool.value_or(project.tools.empty() ? QString() : project.tools.front().id);
  const ToolSpec* tool = project.findTool(tool_id);
  if (!tool) throwBadField("supervisor.tool", "'" + tool_id + "'", "the id of a tool of the project");
  sc.process.tool_radius_m = tool->diameter_mm * 0.5e-3;
  sc.process.teeth = tool->teeth;
  sc.process.spindle_speed_rpm = s.spindle_rpm.value_or(1500.0);
  // The process model resolves a tooth period in at least 8 steps: fast spindles take a finer step.
  sc.process.step_s = std::min(sc.process.step_s, 60.0 / sc.process.spindle_speed_rpm / sc.process.teeth / 8.0);
  sc.programmed_feed_m_per_s = s.programmed_feed_mm_s.value_or(10.0) * 1e-3;
  const SupervisorPartSpec part = s.part.value_or(SupervisorPartSpec{});
  sc.part_length_m = part.length_mm.value_or(100.0) * 1e-3;
  sc.process.part_width_m = part.width_mm.value_or(50.0) * 1e-3;
  sc.approach_m = part.approach_mm.value_or(2.0) * 1e-3;

  const std::optional<std::vector<double>>* passes = s.passes_mm ? s.passes_mm->of(controller) : nullptr;
  if (passes && *passes) {
    sc.pass_depths_m.clear();
    for (double depth_mm : **passes) sc.pass_depths_m.push_back(depth_mm * 1e-3);
  } else {
    sc.pass_depths_m = defaultPassDepths(sc.controller);
  }
  sc.scan_period_s = s.scan_period_ms.value_or(10.0) * 1e-3;
  if (s.reference_force_N) sc.reference_force_N = *s.reference_force_N;
  sc.power_margin = s.power_margin.value_or(sc.power_margin);
  sc.chatter_detector.threshold_N = s.chatter_threshold_N.value_or(sc.chatter_detector.threshold_N);
  if (s.model_controller) {
    if (s.model_controller->time_constant_ms) sc.force_time_constant_s = *s.model_controller->time_constant_ms * 1e-3;
    if (s.model_controller->reset_feed)
      sc.force_reset_feed = parseResetFeed(s.model_controller->reset_feed->toStdString());
  }
  if (project.machine) {
    // P_av at the supervised spindle speed (torque-limited below the base speed).
    sc.limits.spindle_power_limit_W = availablePowerW(project.machine, sc.process.spindle_speed_rpm);
    if (project.machine->max_feed_mm_s) sc.limits.max_feed_rate_m_per_s = *project.machine->max_feed_mm_s * 1e-3;
  }
  if (project.operation) sc.limits.max_feed_per_tooth_m = project.operation->max_feed_per_tooth_mm * 1e-3;

  for (const SupervisorEventSpec& e : s.events.value_or(std::vector<SupervisorEventSpec>{})) {
    OperatorEvent ev;
    ev.t_s = e.t_s;
    if (e.type == "feed_hold_on")
      ev.type = OperatorEventType::FeedHoldOn;
    else if (e.type == "feed_hold_off")
      ev.type = OperatorEventType::FeedHoldOff;
    else
      ev.type = OperatorEventType::ChatterSignal;
    sc.events.push_back(ev);
  }
  try {
    validateSupervisionScenario(sc);
  } catch (const InvalidInput& e) {
    throw ProjectError(QString("supervisor: %1").arg(e.what()));
  }
  r.chart_path = "supervisor.charts." + controller;
  const std::optional<GrafcetChartSpec>* chart = s.charts ? s.charts->of(controller) : nullptr;
  if (!chart || !*chart)
    throw ProjectError(QString("%1 is missing: the Grafcet chart of this controller").arg(r.chart_path));
  checkGrafcetChart((*chart)->chart, r.chart_path, supervisionSignals());
  r.chart = (*chart)->chart;
  return r;
}

SupervisorRequest supervisorRequestFromProject(const Project& project, const QString& controller) {
  if (!supervisorControllers().contains(controller))
    throw InputError(QString("--controller = %1: must be one of none, smc1, smc2").arg(quoted(controller)));
  if (!project.supervisor)
    throw ProjectError("section 'supervisor' is missing: the supervised run needs it (docs/project-file.md)");
  return supervisorRequestFrom(*project.supervisor, project, controller);
}

}  // namespace mx::app
