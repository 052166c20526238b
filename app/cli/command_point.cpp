// millexpert-cli point PROJECT [--tool ID] [--speed RPM] [--depth MM] [--feed MM_PER_TOOTH] [--method zoa|sdm]
//                   [--delta V] [--alpha V] [--steps M] [--dynamics modal|measured]
// The point flags left out are the project's operating_point (the point the GUI saved).
// Everything the lobe chart shows for one operating point: b_lim at the speed (alpha * delta-lobes,
// Rule 1), the stability verdict ("stable": below alpha * b_lim; "verdict": stable, marginal up to 1.05 b_lim, or
// unstable), Delta N_s (2006, section 3.B), ROS (Pareto eq. 13), peak power,
// torque and MRR (Pareto eq. 8), the available spindle power at the speed and the power's fraction of
// it (machine.spindle_power_W, max_torque_Nm, spindle_curve); "dynamics_used" says whether the lobes ran on the
// tap-test FRF (services/measured_dynamics.h).
#include <QJsonArray>
#include <algorithm>
#include <cmath>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_computations.h"
#include "cli/cli_dynamics.h"
#include "cli/cli_support.h"
#include "document/project.h"
#include "document/shortened_text.h"
#include "model/cutting_force.h"
#include "services/cutter_json.h"
#include "services/cutting_data_json.h"
#include "stability/lobe_computation.h"
#include "stability/stability_boundary.h"

namespace mx::app {
namespace {

constexpr double kPointLobeStepRpm = 10.0;
constexpr double kPointSpeedsPerWindow = 1000.0;
constexpr double kMaxPointSpeedRpm = 1e5;  // the --speed flag's top

struct PointLobeSpeeds {
  std::vector<double> values;  // rev/s
  QString range;               // how they came about, for messages
};

// Inside the project's speed range: the lobe chart's own grid, 10 rpm apart, so that the readouts are
// the chart's. Elsewhere (or without a grid): +-50 % around the point on a lattice through the point,
// up to the flag's top, at most 1001 speeds, so that every speed of the flag's range is computed around
// itself.
PointLobeSpeeds pointLobeSpeeds(const Project& project, double speed_rpm) {
  if (project.expert && project.expert->grid) {
    const ExpertGridSpec& g = *project.expert->grid;
    if (speed_rpm >= g.speed_from_rpm && speed_rpm <= g.speed_to_rpm) {
      const double to =
          g.speed_from_rpm + std::ceil((g.speed_to_rpm - g.speed_from_rpm) / kPointLobeStepRpm) * kPointLobeStepRpm;
      return {SpeedGrid{rpmToRevPerS(g.speed_from_rpm), rpmToRevPerS(to), rpmToRevPerS(kPointLobeStepRpm)}.values(),
              QString("expert.grid %1 to %2 rpm by 10 rpm").arg(g.speed_from_rpm).arg(g.speed_to_rpm)};
    }
  }
  const double step = std::max(kPointLobeStepRpm, speed_rpm / kPointSpeedsPerWindow);
  const double below = std::floor(0.5 * speed_rpm / step) * step;
  const double above = std::floor(std::min(0.5 * speed_rpm, kMaxPointSpeedRpm - speed_rpm) / step) * step;
  return {
      SpeedGrid{rpmToRevPerS(speed_rpm - below), rpmToRevPerS(speed_rpm + above), rpmToRevPerS(step)}.values(),
      QString("--speed %1 rpm -50 %/+50 % (at most %2 rpm) by %3 rpm").arg(speed_rpm).arg(kMaxPointSpeedRpm).arg(step)};
}

}  // namespace

QList<QCommandLineOption> pointOptions() {
  QList<QCommandLineOption> options = cutPointOptions();
  options.append({
      {"method", "zoa or sdm (default zoa).", "METHOD", "zoa"},
      {"delta", "Stability margin delta [1/s]; default: the project's.", "V"},
      {"alpha", "Depth factor alpha in (0, 1]; default: the project's.", "V"},
      {"steps",
       "Semi-discretization steps per (mean) tooth period, 4-2000; a variable pitch runs teeth x M per "
       "revolution (default: chosen per speed).",
       "M"},
      {"delay-order", "Semi-discretization: degree 1-3 of the delayed-state interpolation (default 3).", "P"},
      dynamicsCommandOption(),
  });
  return options;
}

QString pointMethod(const QCommandLineParser& parser) {
  QString method = parser.value("method");
  if (method != "zoa" && method != "sdm")
    throw CliError(QString("--method = %1: must be zoa or sdm").arg(quoted(method)), kExitBadInput);
  return method;
}

QJsonObject pointJson(const QCommandLineParser& parser, const Project& project) {
  const QString method = pointMethod(parser);
  const std::optional<DynamicsSource> requested = dynamicsOption(parser);
  const CutPointFlags cut = readCutPoint(parser, project.operating_point);
  const QString& tool = cut.tool;
  const double speed_rpm = cut.speed_rpm, depth_mm = cut.depth_mm, feed_mm = cut.feed_mm_per_tooth;
  double delta = project.expert ? project.expert->delta_per_s : 0.0;
  double alpha = project.expert ? project.expert->alpha : 1.0;
  delta = numberOption(parser, "delta", 0.0, 1e6).value_or(delta);
  alpha = numberOption(parser, "alpha", 1e-9, 1.0).value_or(alpha);
  const int steps = integerOption(parser, "steps", 4, 2000).value_or(kAutoSdmSteps);
  const int delay_order = integerOption(parser, "delay-order", 1, kMaxSdmDelayOrder).value_or(kDefaultSdmDelayOrder);
  const StabilityMethod stability_method =
      method == "zoa" ? StabilityMethod::ZeroOrder : StabilityMethod::SemiDiscretization;
  const DynamicsChoice dynamics = chooseDynamics(requireTool(project, tool), requested, delta, stability_method);
  reportDynamicsNote(dynamics, tool);
  const MillingSetup setup = dynamicsSetupFor(project, tool, dynamics.used);

  const PointLobeSpeeds window = pointLobeSpeeds(project, speed_rpm);
  const std::vector<double>& speeds = window.values;
  if (stability_method == StabilityMethod::SemiDiscretization)
    checkSdmWork(static_cast<double>(speeds.size()), steps, window.range);
  LobeSettings lobe_settings;
  lobe_settings.method = stability_method;
  lobe_settings.dynamics = dynamics.used;
  lobe_settings.delta_per_s = delta;
  lobe_settings.sdm_steps_per_period = steps;
  lobe_settings.sdm_delay_order = delay_order;
  const LobeDiagram diagram = computeLobes(setup, speeds, lobe_settings);
  const StabilityBoundary boundary(diagram, alpha);
  const double n = rpmToRevPerS(speed_rpm), b = depth_mm * 1e-3;
  const CutPerformance perf = evaluateCut(setup, {n, b, feed_mm * 1e-3});
  const double blim = boundary.depthLimit(n);
  const bool stable = boundary.isStable(n, b);

  QJsonObject out{{"tool", tool},
                  {"method", method},
                  {"dynamics_used", dynamicsName(dynamics.used)},
                  {"cutter", cutterJson(setup)},
                  {"cutting_data", cuttingDataJson(setup)},
                  {"speed_rpm", speed_rpm},
                  {"depth_mm", depth_mm},
                  {"feed_per_tooth_mm", feed_mm},
                  {"blim_mm", jsonNumberOrNull(blim * 1e3)},
                  {"stable", stable},
                  {"verdict", verdictKey(boundary.verdict(n, b))},
                  {"delta_Ns_rpm", revPerSToRpm(boundary.speedSecurity(n, b))},
                  {"ROS", jsonNumberOrNull(boundary.robustness(n, b))},
                  {"peak_power_W", perf.peak_power_w},
                  {"mean_power_W", perf.mean_power_w},
                  {"peak_torque_Nm", perf.peak_torque_nm},
                  {"peak_force_N", perf.peak_force_n},
                  {"peak_axial_force_N", perf.peak_axial_force_n},
                  {"MRR_mm3_s", perf.mrr_m3_per_s * 1e9},
                  {"cutting_speed_m_min", perf.cutting_speed_m_per_s * 60.0},
                  {"feed_mm_s", feed_mm * setup.teeth * n}};
  if (const QString note = processDampingNote(stability_method, setup); !note.isEmpty())
    out.insert("notes", QJsonArray{note});
  if (project.machine) {
    const double available = availablePowerW(project.machine, speed_rpm);  // torque-limited below the base speed
    out.insert("available_power_W", available);
    out.insert("power_fraction", perf.peak_power_w / available);
    out.insert("power_ok", perf.peak_power_w <= available);
  }
  const double force_limit = project.toolForceLimitN(requireTool(project, tool));  // Rule 3 F_allow
  if (std::isfinite(force_limit)) {
    out.insert("max_force_N", force_limit);
    out.insert("force_fraction", perf.peak_force_n / force_limit);
    out.insert("force_ok", perf.peak_force_n <= force_limit);
  }
  return out;
}

int runPointCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Stability margin, power and MRR of one operating point.");
  parser.addHelpOption();
  parser.addOptions(pointOptions());
  const QString path = parseSubcommand(parser, arguments);
  pointMethod(parser);  // a bad flag is reported before a bad project
  dynamicsOption(parser);
  printJson(pointJson(parser, loadProject(path)));
  return kExitOk;
}

}  // namespace mx::app
