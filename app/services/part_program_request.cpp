#include "services/part_program_request.h"

#include "document/project_rules.h"
#include "document/shortened_text.h"
#include "gcode/gcode_interpreter.h"
#include "machining/adaptive_path_feeds.h"
#include "machining/depth_profile.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {

const ToolSpec& toolOrFirst(const Project& project, const std::optional<QString>& id, const QString& field) {
  const QString tool_id = id.value_or(project.tools.empty() ? QString() : project.tools.front().id);
  const ToolSpec* tool = project.findTool(tool_id);
  if (!tool) throwBadField(field, "'" + tool_id + "'", "the id of a tool of the project");
  return *tool;
}

}  // namespace

QString OverrideRequest::controllerName() const {
  if (adaptive)
    return QString("adaptive beta-FROH (beta %1, F_r %2 N)")
        .arg(control->settings.beta)
        .arg(control->settings.force_reference_N);
  return QString("model-based F = %1 d^%2 f^%3 (Landers & Ulsoy), F_r %4 N")
      .arg(model->model.K_N)
      .arg(model->model.depth_exponent)
      .arg(model->model.feed_exponent)
      .arg(model->reference_force_N);
}

ModelBasedForceSettings modelBasedSettingsFrom(const ForceControlSection& c, const Project& project) {
  ModelBasedForceSettings s;
  s.teeth = toolOrFirst(project, c.tool, "force_control.tool").teeth;
  const ForceModelSpec m = c.model.value_or(ForceModelSpec{});
  s.model.K_N = m.K_N.value_or(760.0);
  s.model.depth_exponent = m.depth_exponent.value_or(0.65);
  s.model.feed_exponent = m.feed_exponent.value_or(0.63);
  if (!c.reference_force_N) throwMissingField("force_control.reference_force_N", "in (0, 1e7]");
  s.reference_force_N = *c.reference_force_N;
  const double drive = project.machine && project.machine->max_feed_mm_s ? *project.machine->max_feed_mm_s : 36.0;
  s.max_feed_rate_m_per_s = c.max_feed_mm_s.value_or(drive) * 1e-3;
  const double tooth = project.operation ? project.operation->max_feed_per_tooth_mm : 0.6;
  s.max_feed_per_tooth_m = c.max_feed_per_tooth_mm.value_or(tooth) * 1e-3;
  return s;
}

OverrideRequest overrideRequestFrom(const PartProgramSection& p, const Project& project, const QString& controller,
                                    std::optional<double> speed_rpm) {
  OverrideRequest r;
  r.settings.stock_top_z_m = p.stock_top_mm.value_or(0.0) * 1e-3;
  if (p.depth_profile)
    for (const DepthStepSpec& step : *p.depth_profile)
      r.settings.depth_profile.push_back({step.length_mm * 1e-3, step.depth_mm * 1e-3});
  if (p.speed_rpm) r.settings.speed_rev_per_s = *p.speed_rpm / 60.0;
  if (speed_rpm) r.settings.speed_rev_per_s = *speed_rpm / 60.0;
  r.settings.keep_plunge_feed = p.keep_plunge_feed.value_or(true);
  QString choice = controller.isEmpty() ? p.controller.value_or(QString()) : controller;
  if (choice.isEmpty()) choice = project.control ? "adaptive" : "model-based";
  if (choice == "adaptive") {
    r.adaptive = true;
    r.control = controlRequestFromProject(project);
  } else if (choice == "model-based") {
    r.model = modelBasedSettingsFrom(project.force_control.value_or(ForceControlSection{}), project);
  } else {
    throw InputError(QString("--controller = %1: must be adaptive or model-based").arg(quoted(choice)));
  }
  return r;
}

OverrideRequest overrideRequestFromProject(const Project& project, const QString& controller,
                                           std::optional<double> speed_rpm) {
  return overrideRequestFrom(project.part_program.value_or(PartProgramSection{}), project, controller, speed_rpm);
}

OverrideOutcome runOverride(const OverrideRequest& request, const GcodeProgram& program, const JobControl& job) {
  OverrideOutcome out;
  out.controller = request.controllerName();
  if (!request.adaptive) {
    const ModelBasedForceController controller(*request.model);
    out.result = PartProgramOverrider(modelBasedFeedController(controller), request.settings).run(program);
    return out;
  }
  // The adaptive run needs the cutting blocks first: the same interpreter and depth source.
  const GcodeRun run = GcodeInterpreter(request.settings.interpreter).run(program);
  const DepthProfile profile = request.settings.depth_profile.empty()
                                   ? DepthProfile::fromStockTop(request.settings.stock_top_z_m)
                                   : DepthProfile::fromSegments(request.settings.depth_profile);
  const std::vector<CutBlock> cuts = cuttingBlocks(run, profile.blockDepths(run), request.settings.keep_plunge_feed);
  // The spindle speed of the closed loop: the override, else the program's S at the first cut, else
  // control.spindle_rpm.
  AdaptiveControlSettings settings = request.control->settings;
  if (request.settings.speed_rev_per_s > 0.0)
    settings.process.spindle_rev_s = request.settings.speed_rev_per_s;
  else if (!cuts.empty() && run.motions[cuts.front().block].speed_rev_per_s > 0.0)
    settings.process.spindle_rev_s = run.motions[cuts.front().block].speed_rev_per_s;
  const AdaptivePathFeeds feeds(settings, cuts, job);
  out.result = PartProgramOverrider(adaptiveFeedController(feeds), request.settings).run(program);
  out.adaptive_metrics = feeds.run().metrics;
  return out;
}

}  // namespace mx::app
