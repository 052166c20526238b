#include "cli/supervisor_request.h"

#include <QJsonArray>
#include <QJsonObject>

#include "cli/cli_application.h"
#include "cli/cli_support.h"
#include "cli/grafcet_json.h"
#include "model/job_control.h"

namespace mx::app {

const std::set<std::string>& supervisionSignals() {
  static const std::set<std::string> names{"a", "b", "c", "d", "e", "F_Y"};
  return names;
}

QStringList supervisorControllers() { return {"none", "smc1", "smc2"}; }

SupervisorRequest supervisorRequestFromProject(const Project& project, const QString& controller) {
  if (!supervisorControllers().contains(controller))
    failField("--controller", "'" + controller + "'", "one of none, smc1, smc2");
  if (!project.document.value("supervisor").isObject())
    throw CliError("section 'supervisor' is missing: the supervised run needs it (docs/project-file.md)", kExitBadInput);
  const QJsonObject s = project.document.value("supervisor").toObject();
  SupervisorRequest r;
  SupervisionScenario& sc = r.scenario;
  sc.controller = parseController(controller.toStdString());

  const QString tool_id = s.contains("tool") ? s.value("tool").toString()
                                             : (project.tools.empty() ? QString() : project.tools.front().id);
  const ToolSpec* tool = project.findTool(tool_id);
  if (!tool) failField("supervisor.tool", "'" + tool_id + "'", "the id of a tool of the project");
  sc.process.tool_radius_m = tool->diameter_mm * 0.5e-3;
  sc.process.teeth = tool->teeth;
  sc.process.spindle_speed_rpm = sectionNumber(s, "supervisor", "spindle_rpm", 1.0, 1e5, "in [1, 1e5]", 1500.0);
  sc.programmed_feed_m_per_s =
      sectionNumber(s, "supervisor", "programmed_feed_mm_s", 1e-3, 1e4, "in (0, 1e4]", 10.0) * 1e-3;
  const QJsonObject part = s.value("part").toObject();
  sc.part_length_m = sectionNumber(part, "supervisor.part", "length_mm", 1e-3, 1e5, "in (0, 1e5]", 100.0) * 1e-3;
  sc.process.part_width_m = sectionNumber(part, "supervisor.part", "width_mm", 1e-3, 1e4, "in (0, 1e4]", 50.0) * 1e-3;
  sc.approach_m = sectionNumber(part, "supervisor.part", "approach_mm", 0.0, 1e4, "in [0, 1e4]", 2.0) * 1e-3;

  const QJsonValue passes = s.value("passes_mm").toObject().value(controller);
  if (!passes.isUndefined()) {
    if (!passes.isArray() || passes.toArray().isEmpty())
      failField("supervisor.passes_mm." + controller, "(not a non-empty array)", "an array of depths [mm]");
    sc.pass_depths_m.clear();
    const QJsonArray a = passes.toArray();
    for (qsizetype i = 0; i < a.size(); ++i) {
      const QString field = QString("supervisor.passes_mm.%1[%2]").arg(controller).arg(i);
      if (!a[i].isDouble() || !(a[i].toDouble() > 0.0 && a[i].toDouble() <= 20.0))
        failField(field, a[i].toVariant().toString(), "a depth in (0, 20] mm");
      sc.pass_depths_m.push_back(a[i].toDouble() * 1e-3);
    }
  } else {
    sc.pass_depths_m = defaultPassDepths(sc.controller);
  }
  sc.scan_period_s = sectionNumber(s, "supervisor", "scan_period_ms", 0.5, 1000.0, "in [0.5, 1000]", 10.0) * 1e-3;
  if (s.contains("reference_force_N"))
    sc.reference_force_N = sectionNumber(s, "supervisor", "reference_force_N", 1e-3, 1e7, "in (0, 1e7]");
  sc.power_margin = sectionNumber(s, "supervisor", "power_margin", 0.05, 1.0, "in [0.05, 1]", sc.power_margin);
  sc.chatter_detector.threshold_N =
      sectionNumber(s, "supervisor", "chatter_threshold_N", 1e-3, 1e6, "in (0, 1e6]", sc.chatter_detector.threshold_N);
  if (project.machine) {
    sc.limits.spindle_power_limit_W = project.machine->spindle_power_W;
    if (project.machine->max_feed_mm_s) sc.limits.max_feed_rate_m_per_s = *project.machine->max_feed_mm_s * 1e-3;
  }
  if (project.operation) sc.limits.max_feed_per_tooth_m = project.operation->max_feed_per_tooth_mm * 1e-3;

  const QJsonArray events = s.value("events").toArray();
  for (qsizetype i = 0; i < events.size(); ++i) {
    const QString path = QString("supervisor.events[%1]").arg(i);
    const QJsonObject e = events[i].toObject();
    OperatorEvent ev;
    ev.t_s = sectionNumber(e, path, "t_s", 0.0, 1e5, "in [0, 1e5]");
    const QString type = e.value("type").toString();
    if (type == "feed_hold_on")
      ev.type = OperatorEventType::FeedHoldOn;
    else if (type == "feed_hold_off")
      ev.type = OperatorEventType::FeedHoldOff;
    else if (type == "chatter")
      ev.type = OperatorEventType::ChatterSignal;
    else
      failField(path + ".type", "'" + type + "'", "one of feed_hold_on, feed_hold_off, chatter");
    sc.events.push_back(ev);
  }
  try {
    validateSupervisionScenario(sc);
  } catch (const InvalidInput& e) {
    throw CliError(QString("supervisor: %1").arg(e.what()), kExitBadInput);
  }
  r.chart_path = "supervisor.charts." + controller;
  const QJsonValue chart = s.value("charts").toObject().value(controller);
  if (chart.isUndefined()) throw CliError(QString("%1 is missing: the Grafcet chart of this controller").arg(r.chart_path), kExitBadInput);
  r.chart = loadGrafcetChart(chart, r.chart_path, supervisionSignals());
  return r;
}

}  // namespace mx::app
