// millexpert-cli supervise PROJECT --controller none|smc1|smc2 [--csv FILE] [--time-constant-ms MS]
//   [--reset-feed current|model]
// Landers & Ulsoy's supervisory machining control of a face-milling operation: the controller's
// Grafcet chart (the project's supervisor.charts, docs/grafcet.md) run by the Grafcet interpreter, the
// machining modules A-L on their periods, and the face-milling process of the appendix (A1-A12).
// Prints {"controller", "max_power_pct_of_limit", "overshoot_pct", "chatter_detected", "chatter_time_s",
//   "passes", "cycle_time_s", "events": [{"t_s", "type", "detail"}...]} plus "reference_force_N",
//   "max_F_Y_N", "final_program_mm", "steady_max_power_pct_of_limit", "tds_chatter_s", "run_seconds".
// chatter_time_s is null without chatter. --csv: t, F_y, F_Y, power, feed, depth, pass every 2 ms.
// "model_controller": {"time_constant_ms", "reset_feed"} are module L's (SMC I), from the project's
// supervisor.model_controller or the flags; "force_transients": [{"t_s", "peak_F_Y_N", "overshoot_pct",
// "settling_s"}], one per restart of a force controller (L* or K*), settling_s (2 % band) null if it never
// settles.
// --marginal-depth instead prints the appendix's depth search for marginal stability of the project's
// process: {"marginal_depth_mm", "stable_depth_mm", "unstable_depth_mm", "bracketed",
// "trials": [{"depth_mm", "indicator", "chatter"}]} (feed per tooth of the programmed feed).
// Exit 2: bad project, section, chart or flags; exit 1: the run failed.
#include <QJsonArray>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "cli/output_paths.h"
#include "core/invalid_input.h"
#include "grafcet/grafcet_interpreter.h"
#include "services/supervisor_request.h"
#include "supervisor/marginal_depth.h"

namespace mx::app {

namespace {

void writeSeries(const QString& path, const SupervisionResult& r) {
  writeTextFileAtomically("--csv", path, [&](QTextStream& out) {
    out << "t_s,Fy_N,F_Y_N,power_W,feed_mm_s,depth_mm,pass\n";
    for (const SupervisionSample& s : r.series)
      out << s.t_s << ',' << s.fy_N << ',' << s.F_Y_N << ',' << s.power_W << ',' << s.feed_m_per_s * 1e3 << ','
          << s.depth_m * 1e3 << ',' << s.pass << '\n';
  });
}

int printMarginalDepth(const Project& project) {
  const SupervisorRequest request = supervisorRequestFromProject(project, "none");
  const SupervisionScenario& s = request.scenario;
  MarginalDepthSettings settings;
  settings.feed_per_tooth_m = s.programmed_feed_m_per_s / (s.process.teeth * s.process.spindle_speed_rpm / 60.0);
  MarginalDepthResult r;
  try {
    r = MarginalDepthSearch(s.process, settings).search();
  } catch (const InvalidInput& e) {
    throw CliError(QString("supervise: %1").arg(e.what()), kExitBadInput);
  }
  QJsonArray trials;
  for (const DepthTrial& t : r.trials)
    trials.append(QJsonObject{{"depth_mm", t.depth_m * 1e3}, {"indicator", t.indicator}, {"chatter", t.chatter}});
  printJson({{"marginal_depth_mm", r.marginal_depth_m * 1e3},
             {"stable_depth_mm", r.stable_depth_m * 1e3},
             {"unstable_depth_mm", r.unstable_depth_m * 1e3},
             {"bracketed", r.bracketed},
             {"trials", trials}});
  return kExitOk;
}

void applyModelControllerFlags(const QCommandLineParser& parser, SupervisionScenario& s) {
  if (const std::optional<double> ms = numberOption(parser, "time-constant-ms", 1.0, 1e5))
    s.force_time_constant_s = *ms * 1e-3;
  if (!parser.isSet("reset-feed")) return;
  const QString name = parser.value("reset-feed");
  if (name != "current" && name != "model")
    throw CliError(QString("--reset-feed = %1: must be current or model").arg(name), kExitBadInput);
  s.force_reset_feed = parseResetFeed(name.toStdString());
}

}  // namespace

int runSuperviseCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Supervisory machining control of a face-milling operation (Landers & Ulsoy).");
  parser.addHelpOption();
  parser.addOptions({
      {"controller", "none, smc1 or smc2 (required).", "NAME"},
      {"csv", "Write the force and power history to FILE.", "FILE"},
      {"marginal-depth", "Print the depth of marginal stability of the process instead (appendix)."},
      {"time-constant-ms", "Module L's closed-loop force time constant [ms], 1..100000. Default: the project's.", "MS"},
      {"reset-feed", "Where module L restarts at contact: current or model. Default: the project's.", "NAME"},
  });
  const QString path = parseSubcommand(parser, arguments);
  const Project project = OutputPaths().outputOption(parser, "csv").loadProject(path);
  if (parser.isSet("marginal-depth")) return printMarginalDepth(project);
  const QString controller = requiredOption(parser, "controller");
  SupervisorRequest request = supervisorRequestFromProject(project, controller);
  applyModelControllerFlags(parser, request.scenario);
  SupervisionResult r;
  try {
    GrafcetInterpreter logic(request.chart);
    r = runSupervision(request.scenario, logic);
  } catch (const InvalidInput& e) {
    throw CliError(QString("supervise: %1").arg(e.what()), kExitBadInput);
  } catch (const std::exception& e) {
    throw CliError(QString("supervise: the run failed: %1").arg(e.what()), kExitComputationFailed);
  }
  if (parser.isSet("csv")) writeSeries(parser.value("csv"), r);
  const SupervisionMetrics& m = r.metrics;
  QJsonArray events, program;
  for (const SupervisionEvent& e : r.events)
    events.append(QJsonObject{
        {"t_s", e.t_s}, {"type", QString::fromStdString(e.type)}, {"detail", QString::fromStdString(e.detail)}});
  for (double d : r.final_program_m) program.append(d * 1e3);
  QJsonArray transients;
  for (const ForceTransient& t : m.force_transients)
    transients.append(QJsonObject{{"t_s", t.t_s},
                                  {"peak_F_Y_N", t.peak_F_Y_N},
                                  {"overshoot_pct", t.overshoot_pct},
                                  {"settling_s", t.settling_s >= 0.0 ? QJsonValue(t.settling_s) : QJsonValue()}});
  const QJsonObject model_controller{
      {"time_constant_ms", request.scenario.force_time_constant_s * 1e3},
      {"reset_feed", QString::fromStdString(resetFeedName(request.scenario.force_reset_feed))}};
  printJson({{"controller", controller},
             {"max_power_pct_of_limit", m.max_power_pct_of_limit},
             {"overshoot_pct", m.overshoot_pct},
             {"chatter_detected", m.chatter_detected},
             {"chatter_time_s", m.chatter_time_s >= 0.0 ? QJsonValue(m.chatter_time_s) : QJsonValue()},
             {"passes", m.passes},
             {"cycle_time_s", m.cycle_time_s},
             {"events", events},
             {"reference_force_N", m.reference_force_N},
             {"max_F_Y_N", m.max_F_Y_N},
             {"steady_max_power_pct_of_limit", m.steady_max_power_pct_of_limit},
             {"tds_chatter_s", m.tds_chatter_s},
             {"final_program_mm", program},
             {"model_controller", model_controller},
             {"force_transients", transients},
             {"run_seconds", m.run_seconds}});
  return kExitOk;
}

}  // namespace mx::app
