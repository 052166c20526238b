// millexpert-cli lobes PROJECT --tool ID [--method zoa|sdm] [--from RPM --to RPM --step RPM]
//                  [--delta V] [--alpha V] [--steps M] [--delay-order P] [--helix-slices N]
//                  [--max-depth MM] [--dynamics modal|measured]
// Prints {"tool","method","dynamics_used","cutter","speed_rpm":[...],"blim_mm":[...]} (with sdm also
// "sdm_delay_order", "sdm_helix_slices" and "sdm_steps", per speed): alpha times the
// delta-margined lower envelope (Rule 1), null where no instability lies below --max-depth. With
// measured dynamics the ZOA runs on the tap-test FRF; delta > 0 or sdm use the fitted modes
// (services/measured_dynamics.h), and stderr says so.
#include <QJsonArray>
#include <cmath>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_computations.h"
#include "cli/cli_dynamics.h"
#include "cli/cli_support.h"
#include "document/lobe_inputs.h"
#include "document/project.h"
#include "document/shortened_text.h"
#include "services/cutter_json.h"
#include "services/cutting_data_json.h"
#include "stability/lobe_computation.h"

namespace mx::app {

namespace {

constexpr double kMaxZoaLobeSpeeds = 200000;  // about 0.5 s

struct LobesRequest {
  QString tool;
  QString method = "zoa";
  SpeedGrid grid;
  double from_rpm = 0.0;
  double step_rpm = 0.0;
  double delta_per_s = 0.0;
  double alpha = 1.0;
  int steps = kAutoSdmSteps;
  int delay_order = kDefaultSdmDelayOrder;
  int helix_slices = kExactHelixSlices;
  double max_depth_m = 0.02;
  std::optional<DynamicsSource> dynamics;
};

// The lobes' cost grows with the speeds, the semi-discretization's also with its steps; the message
// names where each number came from (a flag, else the project's grid).
void checkSpeedCount(const QCommandLineParser& parser, const LobesRequest& r, double from, double to, double step) {
  const double count = std::floor((to - from) / step + 1e-9) + 1.0;
  const auto source = [&](const char* flag, const char* field) {
    return parser.isSet(flag) ? QString("--%1").arg(flag) : QString("expert.grid.%1").arg(field);
  };
  const QString range = QString("%1 = %2 to %3 = %4 by %5 = %6 rpm")
                            .arg(source("from", "speed_from_rpm"))
                            .arg(from)
                            .arg(source("to", "speed_to_rpm"))
                            .arg(to)
                            .arg(source("step", "speed_step_rpm"))
                            .arg(step);
  if (r.method == "sdm") return checkSdmWork(count, r.steps, range);
  if (count > kMaxZoaLobeSpeeds)
    throw CliError(QString("%1 gives %2 speeds: the zoa lobes take at most %3; raise the step or narrow the range")
                       .arg(range)
                       .arg(count, 0, 'f', 0)
                       .arg(kMaxZoaLobeSpeeds, 0, 'f', 0),
                   kExitBadInput);
}

LobesRequest readRequest(const QCommandLineParser& parser, const Project& project) {
  LobesRequest r;
  r.tool = requiredOption(parser, "tool");
  r.method = parser.value("method");
  if (r.method != "zoa" && r.method != "sdm")
    throw CliError(QString("--method = %1: must be zoa or sdm").arg(quoted(r.method)), kExitBadInput);
  const LobeInputs inputs = lobeInputsFrom(project, gridStepRpm(project, 100.0));
  const double from = numberOption(parser, "from", 1e-3, 1e5).value_or(inputs.from_rpm);
  const double to = numberOption(parser, "to", 1e-3, 1e5).value_or(inputs.to_rpm);
  const double step = numberOption(parser, "step", 1e-3, 1e5).value_or(inputs.step_rpm);
  if (to < from) throw CliError(QString("--to = %1: must be >= --from (%2)").arg(to).arg(from), kExitBadInput);
  r.grid = {rpmToRevPerS(from), rpmToRevPerS(to), rpmToRevPerS(step)};
  r.from_rpm = from;
  r.step_rpm = step;
  r.delta_per_s = numberOption(parser, "delta", 0.0, 1e6).value_or(inputs.delta_per_s);
  r.alpha = numberOption(parser, "alpha", 1e-9, 1.0).value_or(inputs.alpha);
  r.steps = integerOption(parser, "steps", 4, 2000).value_or(r.steps);
  checkSpeedCount(parser, r, from, to, step);
  r.delay_order = integerOption(parser, "delay-order", 1, kMaxSdmDelayOrder).value_or(r.delay_order);
  r.helix_slices = integerOption(parser, "helix-slices", 0, kMaxHelixSlices).value_or(r.helix_slices);
  r.max_depth_m = numberOption(parser, "max-depth", 1e-6, 1e4).value_or(20.0) * 1e-3;
  r.dynamics = dynamicsOption(parser);
  return r;
}

}  // namespace

QList<QCommandLineOption> lobesOptions() {
  return {
      {"tool", "Tool id.", "ID"},
      {"method", "zoa (zeroth-order approximation) or sdm (semi-discretization).", "METHOD", "zoa"},
      {"from", "First speed [rpm]; default: the project's expert grid, else 1000.", "RPM"},
      {"to", "Last speed [rpm]; default: the project's expert grid, else 20000.", "RPM"},
      {"step", "Speed step [rpm]; default: the project's expert grid, else 100.", "RPM"},
      {"delta", "Stability margin delta [1/s] (Rule 1.1); default: the project's.", "V"},
      {"alpha", "Depth factor alpha in (0, 1] (Rule 1.2); default: the project's.", "V"},
      {"steps",
       "Semi-discretization steps per (mean) tooth period, 4-2000; a variable pitch runs teeth x M per "
       "revolution (default: chosen per speed).",
       "M"},
      {"max-depth", "Depth cap [mm]: null where no instability below it (default 20).", "MM"},
      {"delay-order", "Semi-discretization: degree 1-3 of the delayed-state interpolation (default 3).", "P"},
      {"helix-slices",
       "Semi-discretization: axial slices of a helical edge, 1-1000; 0 (default) integrates the helix lag "
       "exactly.",
       "N"},
      dynamicsCommandOption(),
  };
}

QJsonObject lobesJson(const QCommandLineParser& parser, const Project& project) {
  const LobesRequest request = readRequest(parser, project);
  const StabilityMethod method =
      request.method == "zoa" ? StabilityMethod::ZeroOrder : StabilityMethod::SemiDiscretization;
  const DynamicsChoice dynamics =
      chooseDynamics(requireTool(project, request.tool), request.dynamics, request.delta_per_s, method);
  reportDynamicsNote(dynamics, request.tool);
  const MillingSetup setup = dynamicsSetupFor(project, request.tool, dynamics.used);
  // The grid in rpm as the user gave it (exact values in the output), converted once to SI.
  const std::vector<double> speeds = request.grid.values();
  std::vector<double> rpm_values;
  for (size_t i = 0; i < speeds.size(); ++i)
    rpm_values.push_back(request.from_rpm + static_cast<double>(i) * request.step_rpm);

  const LobeDiagram diagram = computeLobes(setup, speeds,
                                           {method, request.delta_per_s, request.max_depth_m, request.steps,
                                            dynamics.used, request.delay_order, request.helix_slices});

  QJsonArray speed_rpm, blim_mm, chatter_hz, minima;
  for (size_t i = 0; i < speeds.size(); ++i) {
    speed_rpm.append(rpm_values[i]);
    const double b = diagram.envelope_depth_m[i];
    blim_mm.append(jsonNumberOrNull(std::isfinite(b) ? request.alpha * b * 1e3 : b));
    chatter_hz.append(std::isfinite(b) ? jsonNumberOrNull(diagram.envelope_chatter_hz[i]) : QJsonValue());
  }
  for (const LobeMinimum& m : diagram.minima)
    minima.append(QJsonObject{{"speed_rpm", revPerSToRpm(m.speed_rev_per_s)},
                              {"blim_mm", request.alpha * m.depth_m * 1e3},
                              {"chatter_frequency_Hz", m.chatter_hz}});
  QJsonObject out{{"tool", request.tool},
                  {"method", request.method},
                  {"dynamics_used", dynamicsName(dynamics.used)},
                  {"delta_per_s", request.delta_per_s},
                  {"alpha", request.alpha},
                  {"cutter", cutterJson(setup)},
                  {"cutting_data", cuttingDataJson(setup)},
                  {"speed_rpm", speed_rpm},
                  {"blim_mm", blim_mm},
                  {"chatter_frequency_Hz", chatter_hz},
                  {"minima", minima}};
  if (const QString note = processDampingNote(method, setup); !note.isEmpty()) out.insert("notes", QJsonArray{note});
  if (method == StabilityMethod::SemiDiscretization) {
    out.insert("sdm_delay_order", request.delay_order);
    out.insert("sdm_helix_slices", request.helix_slices);
    QJsonArray steps;  // per speed: the steps per tooth period used
    for (double n : speeds) steps.append(request.steps == kAutoSdmSteps ? autoSdmSteps(setup, n) : request.steps);
    out.insert("sdm_steps", steps);
  }
  return out;
}

int runLobesCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Stability lobes of one tool: alpha * delta-margined b_lim(N).");
  parser.addHelpOption();
  parser.addOptions(lobesOptions());
  const QString path = parseSubcommand(parser, arguments);
  printJson(lobesJson(parser, loadProject(path)));
  return kExitOk;
}

}  // namespace mx::app
