#include "services/control_request.h"

#include <cmath>
#include <numbers>

#include "core/invalid_input.h"
#include "document/project_rules.h"
#include "document/project_validation.h"

namespace mx::app {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

CovarianceReset resetOf(const QString& r) {
  if (r == "trace") return CovarianceReset::Trace;
  if (r == "none") return CovarianceReset::None;
  return CovarianceReset::ErrorFraction;
}

QString resetName(CovarianceReset r) {
  switch (r) {
    case CovarianceReset::ErrorFraction:
      return "error";
    case CovarianceReset::Trace:
      return "trace";
    case CovarianceReset::None:
      break;
  }
  return "none";
}

// Default engagement: the engine's immersion of the tool's radial depth (tool.radial_depth_mm, else
// the operation's), as for the stability model; full immersion without an operation.
void engagementOf(const Project& p, const ToolSpec& tool, CuttingProcess& c) {
  if (!p.operation) return;
  const std::optional<double> depth_mm = radialDepthMm(p, tool);
  if (!depth_mm) return;
  const Immersion im = Immersion::fromRadialDepth(*depth_mm * 1e-3, tool.diameter_mm * 1e-3, p.operation->milling);
  c.start_angle_rad = im.entry_rad;
  c.exit_angle_rad = im.exit_rad;
}

SamplePeriodRule samplePeriodOf(const std::optional<QString>& name) {
  return name && *name == "rule4" ? SamplePeriodRule::Rule4 : SamplePeriodRule::Spindle;
}

void programmeOf(const std::vector<ControlProgrammePointSpec>& points, ControlRequest& r) {
  r.programme = true;
  r.settings.workpiece.steps.clear();
  for (const ControlProgrammePointSpec& point : points) {
    ControlDepthStep step;
    step.length_m = point.length_mm * 1e-3;
    step.depth_m = point.depth_mm * 1e-3;
    step.spindle_rev_s = point.speed_rpm / 60.0;
    r.settings.workpiece.steps.push_back(step);
    r.programmed_feed_m_s.push_back(point.feed_mm_s ? std::optional<double>(*point.feed_mm_s * 1e-3) : std::nullopt);
  }
}

}  // namespace

ControlRequest controlRequestFrom(const ControlSection& c, const Project& project) {
  ControlRequest r;
  if (project.tools.empty()) throw ProjectError("tools: the project has no tool");
  r.tool = c.tool.value_or(project.tools.front().id);
  const ToolSpec* tool = project.findTool(r.tool);
  if (!tool) throwBadField("control.tool", "'" + r.tool + "'", "the id of a tool of the project");
  const bool programme = c.programme && !c.programme->empty();
  if (!c.spindle_rpm && !programme) throwMissingField("control.spindle_rpm", "in (0, 100000]");

  AdaptiveControlSettings& s = r.settings;
  CuttingProcess& p = s.process;
  p.teeth = tool->teeth;
  p.spindle_rev_s = (programme ? c.programme->front().speed_rpm : *c.spindle_rpm) / 60.0;
  const double kt = project.material ? project.material->Kt_N_mm2 : 0.0;
  if (!c.cutting_pressure_N_mm2 && !(kt > 0.0)) throwMissingField("control.cutting_pressure_N_mm2", "in (0, 1e6]");
  p.cutting_pressure_Pa = c.cutting_pressure_N_mm2.value_or(kt) * 1e6;
  engagementOf(project, *tool, p);
  p.start_angle_rad = c.start_angle_deg.value_or(p.start_angle_rad / kDeg) * kDeg;
  p.exit_angle_rad = c.exit_angle_deg.value_or(p.exit_angle_rad / kDeg) * kDeg;
  if (!(p.exit_angle_rad > p.start_angle_rad))
    throwBadField("control.exit_angle_deg", QString::number(p.exit_angle_rad / kDeg),
                  "greater than control.start_angle_deg");
  p.drive_time_constant_s = c.drive_time_constant_ms.value_or(0.1) * 1e-3;
  p.process_time_constant_s = c.process_time_constant_ms.value_or(0.0) * 1e-3;
  s.beta = c.beta.value_or(0.0);
  s.feed_max_m_s = c.feed_max_mm_s.value_or(30.0) * 1e-3;

  if (c.force_reference_N) {
    s.force_reference_N = *c.force_reference_N;
    r.reference.force_N = s.force_reference_N;
    r.reference.binding = "project";
  } else {
    ToolForceLimits limits;
    limits.breakage_force_N = c.breakage_force_N.value_or(0.0);
    limits.safety_factor = c.safety_factor.value_or(1.0);
    limits.spindle_power_W = project.machine ? availablePowerW(project.machine, p.spindle_rev_s * 60.0) : 0.0;
    limits.tool_diameter_m = tool->diameter_mm * 1e-3;
    limits.spindle_rev_s = p.spindle_rev_s;
    try {
      r.reference = forceReferenceFromLimits(limits);
    } catch (const InvalidInput& e) {
      throw ProjectError(QString("control: no force reference: %1 (give control.force_reference_N, or "
                                 "control.breakage_force_N and machine.spindle_power_W)")
                             .arg(e.what()));
    }
    s.force_reference_N = r.reference.force_N;
  }

  const ControlReferenceModelSpec m = c.reference_model.value_or(ControlReferenceModelSpec{});
  s.damping_ratio = m.damping.value_or(0.75);
  s.rise_time_periods = m.rise_time_periods.value_or(4.0);

  const ControlRlsSpec rls = c.rls.value_or(ControlRlsSpec{});
  s.rls.forgetting_factor = rls.lambda.value_or(1.0);
  s.rls.initial_covariance = rls.P0.value_or(1e5);
  s.rls.initial_parameter = rls.theta0.value_or(0.2);
  s.rls.reset = resetOf(rls.reset.value_or("error"));
  s.rls.reset_error_fraction = rls.reset_fraction.value_or(0.05);
  s.rls.trace_min = rls.trace_min.value_or(1e-6);
  s.rls.trace_max = rls.trace_max.value_or(1e12);

  if (c.workpiece) {
    s.workpiece.steps.clear();
    for (const DepthStepSpec& step : *c.workpiece)
      s.workpiece.steps.push_back({step.length_mm * 1e-3, step.depth_mm * 1e-3, 0.0});
  }
  if (programme) programmeOf(*c.programme, r);
  s.sample_period = samplePeriodOf(c.sample_period);
  s.rule4_periods = static_cast<int>(c.rule4_periods.value_or(4.0));
  try {
    validateAdaptiveControlSettings(s);
  } catch (const InvalidInput& e) {
    throw ProjectError(QString("control: %1").arg(e.what()));
  }
  return r;
}

ControlRequest controlRequestFromProject(const Project& project) {
  if (!project.control)
    throw ProjectError("section 'control' is missing: the adaptive force controller needs it (docs/project-file.md)");
  return controlRequestFrom(*project.control, project);
}

ControlSection controlSectionFrom(const ControlRequest& request, ControlSection c) {
  const AdaptiveControlSettings& s = request.settings;
  c.tool = request.tool;
  if (s.sample_period == SamplePeriodRule::Rule4 || c.sample_period)
    c.sample_period = s.sample_period == SamplePeriodRule::Rule4 ? "rule4" : "spindle";
  if (s.rule4_periods != 4 || c.rule4_periods) c.rule4_periods = s.rule4_periods;
  if (!request.programme) c.spindle_rpm = s.process.spindle_rev_s * 60.0;
  c.process_time_constant_ms = s.process.process_time_constant_s * 1e3;
  c.beta = s.beta;
  c.feed_max_mm_s = s.feed_max_m_s * 1e3;
  if (request.reference.binding == "project") c.force_reference_N = s.force_reference_N;
  c.reference_model = ControlReferenceModelSpec{s.damping_ratio, s.rise_time_periods};
  ControlRlsSpec rls = c.rls.value_or(ControlRlsSpec{});
  rls.lambda = s.rls.forgetting_factor;
  rls.P0 = s.rls.initial_covariance;
  rls.theta0 = s.rls.initial_parameter;
  rls.reset = resetName(s.rls.reset);
  rls.reset_fraction = s.rls.reset_error_fraction;
  c.rls = rls;
  if (request.programme) {  // the steps back into the programme's points, which keep their own feeds
    std::vector<ControlProgrammePointSpec> points;
    for (std::size_t i = 0; i < s.workpiece.steps.size(); ++i) {
      const ControlDepthStep& step = s.workpiece.steps[i];
      ControlProgrammePointSpec point =
          c.programme && i < c.programme->size() ? (*c.programme)[i] : ControlProgrammePointSpec{};
      point.speed_rpm = stepProcess(s.process, step).spindle_rev_s * 60.0;
      point.depth_mm = step.depth_m * 1e3;
      point.length_mm = step.length_m * 1e3;
      points.push_back(point);
    }
    c.programme = points;
    return c;
  }
  std::vector<DepthStepSpec> steps;
  for (const ControlDepthStep& step : s.workpiece.steps) steps.push_back({step.length_m * 1e3, step.depth_m * 1e3, {}});
  c.workpiece = steps;
  return c;
}

}  // namespace mx::app
