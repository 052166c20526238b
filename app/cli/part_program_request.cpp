#include "cli/part_program_request.h"

#include <QJsonArray>
#include <QJsonObject>

#include "cli/cli_application.h"
#include "cli/cli_support.h"
#include "control/adaptive_path_feeds.h"
#include "io/depth_profile.h"
#include "io/gcode_interpreter.h"

namespace mx::app {

namespace {

ModelBasedForceSettings modelSettings(const Project& project) {
  const QJsonObject c = project.document.value("force_control").toObject();
  ModelBasedForceSettings s;
  const QString tool_id = c.contains("tool") ? c.value("tool").toString()
                                             : (project.tools.empty() ? QString() : project.tools.front().id);
  const ToolSpec* tool = project.findTool(tool_id);
  if (!tool) failField("force_control.tool", "'" + tool_id + "'", "the id of a tool of the project");
  s.teeth = tool->teeth;
  const QJsonObject m = c.value("model").toObject();
  s.model.K_N = sectionNumber(m, "force_control.model", "K_N", 1e-6, 1e9, "in (0, 1e9]", 760.0);
  s.model.depth_exponent = sectionNumber(m, "force_control.model", "depth_exponent", 0.01, 5.0, "in [0.01, 5]", 0.65);
  s.model.feed_exponent = sectionNumber(m, "force_control.model", "feed_exponent", 0.01, 5.0, "in [0.01, 5]", 0.63);
  s.reference_force_N = sectionNumber(c, "force_control", "reference_force_N", 1e-3, 1e7, "in (0, 1e7]");
  const double drive = project.machine && project.machine->max_feed_mm_s ? *project.machine->max_feed_mm_s : 36.0;
  s.max_feed_rate_m_per_s = sectionNumber(c, "force_control", "max_feed_mm_s", 1e-3, 1e5, "in (0, 1e5]", drive) * 1e-3;
  const double tooth = project.operation ? project.operation->max_feed_per_tooth_mm : 0.6;
  s.max_feed_per_tooth_m =
      sectionNumber(c, "force_control", "max_feed_per_tooth_mm", 1e-4, 100.0, "in (0, 100]", tooth) * 1e-3;
  return s;
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

OverrideRequest overrideRequestFromProject(const Project& project, const QString& controller,
                                           std::optional<double> speed_rpm) {
  const QJsonObject p = project.document.value("part_program").toObject();
  OverrideRequest r;
  r.settings.stock_top_z_m = sectionNumber(p, "part_program", "stock_top_mm", -1e5, 1e5, "in [-1e5, 1e5]", 0.0) * 1e-3;
  if (p.contains("depth_profile"))
    for (const auto& [length, depth] : depthStepsField(p.value("depth_profile"), "part_program.depth_profile"))
      r.settings.depth_profile.push_back({length, depth});
  if (p.contains("speed_rpm"))
    r.settings.speed_rev_per_s = sectionNumber(p, "part_program", "speed_rpm", 1e-3, 1e6, "in (0, 1e6]") / 60.0;
  if (speed_rpm) r.settings.speed_rev_per_s = *speed_rpm / 60.0;
  r.settings.keep_plunge_feed = p.value("keep_plunge_feed").toBool(true);
  QString choice = controller.isEmpty() ? p.value("controller").toString() : controller;
  if (choice.isEmpty()) choice = project.document.contains("control") ? "adaptive" : "model-based";
  if (choice == "adaptive") {
    r.adaptive = true;
    r.control = controlRequestFromProject(project);
  } else if (choice == "model-based") {
    r.model = modelSettings(project);
  } else {
    failField(controller.isEmpty() ? "part_program.controller" : "--controller", "'" + choice + "'",
              "adaptive or model-based");
  }
  return r;
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
