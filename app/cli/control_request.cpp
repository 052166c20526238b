#include "cli/control_request.h"

#include <QJsonArray>
#include <cmath>
#include <numbers>

#include "cli/cli_application.h"
#include "cli/cli_support.h"
#include "model/job_control.h"

namespace mx::app {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

CovarianceReset parseReset(const QJsonObject& rls) {
  const QString r = rls.value("reset").toString("error");
  if (r == "error") return CovarianceReset::ErrorFraction;
  if (r == "trace") return CovarianceReset::Trace;
  if (r == "none") return CovarianceReset::None;
  failField("control.rls.reset", "'" + r + "'", "one of error, trace, none");
}

QString resetName(CovarianceReset r) {
  switch (r) {
    case CovarianceReset::ErrorFraction: return "error";
    case CovarianceReset::Trace: return "trace";
    case CovarianceReset::None: break;
  }
  return "none";
}

// Default engagement from the operation: full immersion, or the radial immersion a/D for up (from 0)
// or down milling (to pi).
void engagementFromOperation(const Project& p, CuttingProcess& c) {
  if (!p.operation || !p.operation->radial_immersion) return;
  const double ratio = *p.operation->radial_immersion;
  const double phi = std::acos(std::clamp(1.0 - 2.0 * ratio, -1.0, 1.0));
  if (p.operation->milling == MillingDirection::Down) {
    c.start_angle_rad = std::numbers::pi - phi;
    c.exit_angle_rad = std::numbers::pi;
  } else {
    c.start_angle_rad = 0.0;
    c.exit_angle_rad = phi;
  }
}

}  // namespace

ControlRequest controlRequestFromProject(const Project& project) {
  if (!project.document.value("control").isObject())
    throw CliError("section 'control' is missing: the adaptive force controller needs it (docs/project-file.md)",
                   kExitBadInput);
  const QJsonObject c = project.document.value("control").toObject();
  ControlRequest r;
  if (project.tools.empty()) throw CliError("tools: the project has no tool", kExitBadInput);
  r.tool = c.contains("tool") ? c.value("tool").toString() : project.tools.front().id;
  const ToolSpec* tool = project.findTool(r.tool);
  if (!tool) failField("control.tool", "'" + r.tool + "'", "the id of a tool of the project");

  AdaptiveControlSettings& s = r.settings;
  CuttingProcess& p = s.process;
  p.teeth = tool->teeth;
  p.spindle_rev_s = sectionNumber(c, "control", "spindle_rpm", 1e-3, 1e5, "in (0, 100000]") / 60.0;
  const double kt = project.material ? project.material->Kt_N_mm2 : 0.0;
  p.cutting_pressure_Pa =
      sectionNumber(c, "control", "cutting_pressure_N_mm2", 1e-3, 1e6, "in (0, 1e6]", kt > 0 ? std::optional(kt) : std::nullopt) * 1e6;
  engagementFromOperation(project, p);
  p.start_angle_rad = sectionNumber(c, "control", "start_angle_deg", 0.0, 180.0, "in [0, 180]", p.start_angle_rad / kDeg) * kDeg;
  p.exit_angle_rad = sectionNumber(c, "control", "exit_angle_deg", 0.0, 180.0, "in [0, 180]", p.exit_angle_rad / kDeg) * kDeg;
  if (!(p.exit_angle_rad > p.start_angle_rad))
    failField("control.exit_angle_deg", QString::number(p.exit_angle_rad / kDeg), "greater than control.start_angle_deg");
  p.drive_time_constant_s = sectionNumber(c, "control", "drive_time_constant_ms", 1e-6, 1e4, "in (0, 1e4]", 0.1) * 1e-3;
  p.process_time_constant_s = sectionNumber(c, "control", "process_time_constant_ms", 0.0, 1e4, "in [0, 1e4] (0: default)", 0.0) * 1e-3;
  s.beta = sectionNumber(c, "control", "beta", -1.0, 1.0, "in [-1, 1]", 0.0);
  s.feed_max_m_s = sectionNumber(c, "control", "feed_max_mm_s", 1e-3, 1e5, "in (0, 1e5]", 30.0) * 1e-3;

  if (c.contains("force_reference_N")) {
    s.force_reference_N = sectionNumber(c, "control", "force_reference_N", 1e-3, 1e7, "in (0, 1e7]");
    r.reference.force_N = s.force_reference_N;
    r.reference.binding = "project";
  } else {
    ToolForceLimits limits;
    limits.breakage_force_N = sectionNumber(c, "control", "breakage_force_N", 0.0, 1e7, "in [0, 1e7] (0: not given)", 0.0);
    limits.safety_factor = sectionNumber(c, "control", "safety_factor", 1e-3, 1.0, "in (0, 1]", 1.0);
    limits.spindle_power_W = project.machine ? project.machine->spindle_power_W : 0.0;
    limits.tool_diameter_m = tool->diameter_mm * 1e-3;
    limits.spindle_rev_s = p.spindle_rev_s;
    try {
      r.reference = forceReferenceFromLimits(limits);
    } catch (const InvalidInput& e) {
      throw CliError(QString("control: no force reference: %1 (give control.force_reference_N, or "
                             "control.breakage_force_N and machine.spindle_power_W)")
                         .arg(e.what()),
                     kExitBadInput);
    }
    s.force_reference_N = r.reference.force_N;
  }

  const QJsonObject m = c.value("reference_model").toObject();
  s.damping_ratio = sectionNumber(m, "control.reference_model", "damping", 0.05, 5.0, "in [0.05, 5]", 0.75);
  s.rise_time_periods = sectionNumber(m, "control.reference_model", "rise_time_periods", 0.5, 1000.0, "in [0.5, 1000]", 4.0);

  const QJsonObject rls = c.value("rls").toObject();
  s.rls.forgetting_factor = sectionNumber(rls, "control.rls", "lambda", 0.5, 1.0, "in [0.5, 1]", 1.0);
  s.rls.initial_covariance = sectionNumber(rls, "control.rls", "P0", 1e-6, 1e15, "in [1e-6, 1e15]", 1e5);
  s.rls.initial_parameter = sectionNumber(rls, "control.rls", "theta0", -1e6, 1e6, "in [-1e6, 1e6]", 0.2);
  s.rls.reset = parseReset(rls);
  s.rls.reset_error_fraction = sectionNumber(rls, "control.rls", "reset_fraction", 1e-6, 10.0, "in (0, 10]", 0.05);
  s.rls.trace_min = sectionNumber(rls, "control.rls", "trace_min", 0.0, 1e15, "in [0, 1e15]", 1e-6);
  s.rls.trace_max = sectionNumber(rls, "control.rls", "trace_max", 1e-12, 1e300, "in (0, 1e300]", 1e12);
  if (!(s.rls.trace_max > s.rls.trace_min))
    failField("control.rls.trace_max", QString::number(s.rls.trace_max), "greater than control.rls.trace_min");

  if (c.contains("workpiece")) {
    s.workpiece.steps.clear();
    for (const auto& [length, depth] : depthStepsField(c.value("workpiece"), "control.workpiece"))
      s.workpiece.steps.push_back({length, depth});
  }
  try {
    validateAdaptiveControlSettings(s);
  } catch (const InvalidInput& e) {
    throw CliError(QString("control: %1").arg(e.what()), kExitBadInput);
  }
  return r;
}

QJsonObject controlSectionJson(const ControlRequest& request, const QJsonObject& previous) {
  const AdaptiveControlSettings& s = request.settings;
  QJsonObject c = previous;
  c.insert("tool", request.tool);
  c.insert("spindle_rpm", s.process.spindle_rev_s * 60.0);
  c.insert("process_time_constant_ms", s.process.process_time_constant_s * 1e3);
  c.insert("beta", s.beta);
  c.insert("feed_max_mm_s", s.feed_max_m_s * 1e3);
  if (request.reference.binding == "project") c.insert("force_reference_N", s.force_reference_N);
  c.insert("reference_model", QJsonObject{{"damping", s.damping_ratio}, {"rise_time_periods", s.rise_time_periods}});
  QJsonObject rls = previous.value("rls").toObject();
  rls.insert("lambda", s.rls.forgetting_factor);
  rls.insert("P0", s.rls.initial_covariance);
  rls.insert("theta0", s.rls.initial_parameter);
  rls.insert("reset", resetName(s.rls.reset));
  rls.insert("reset_fraction", s.rls.reset_error_fraction);
  c.insert("rls", rls);
  QJsonArray steps;
  for (const ControlDepthStep& step : s.workpiece.steps)
    steps.append(QJsonObject{{"length_mm", step.length_m * 1e3}, {"depth_mm", step.depth_m * 1e3}});
  c.insert("workpiece", steps);
  return c;
}

}  // namespace mx::app
