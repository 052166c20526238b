// millexpert-cli simulate PROJECT [--tool ID] [--speed RPM] [--depth MM] [--feed MM_PER_TOOTH]
//                     [--revolutions N] [--csv FILE] [--ssv-amplitude A --ssv-frequency HZ]
//                     [--passes K] [--axial-slices N]
// Time-domain simulation (Rubio et al. 2006 eq. 1-7, RK4) with the chatter indicators (eq. 11,
// Pareto Rule 15) and the Smith-Tlusty suggested speed (Rule 16). The point flags left out are the
// project's operating_point.
#include <QSaveFile>
#include <QTextStream>
#include <algorithm>
#include <cmath>
#include <limits>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_dynamics.h"
#include "cli/cli_support.h"
#include "cli/output_paths.h"
#include "document/project.h"
#include "model/axial_slices.h"
#include "services/cutter_json.h"
#include "services/cutting_data_json.h"
#include "simulation/simulation.h"
#include "simulation/time_domain_simulator.h"

namespace mx::app {

namespace {

void writeCsv(const QString& path, const SimulationTrace& trace) {
  writeTextFileAtomically("--csv", path, [&](QTextStream& out) {
    out << "time_s,x_mm,y_mm,Fx_N,Fy_N,F_N,P_W\n";
    for (size_t i = 0; i < trace.time_s.size(); ++i)
      out << trace.time_s[i] << ',' << trace.x_m[i] * 1e3 << ',' << trace.y_m[i] * 1e3 << ',' << trace.fx_n[i] << ','
          << trace.fy_n[i] << ',' << trace.force_n[i] << ',' << trace.power_w[i] << '\n';
  });
}

// The run's size against the engine's limits, worded by the flags that set it.
void checkSimulationSize(const MillingSetup& setup, const OperatingPoint& point, const SimulationOptions& options,
                         const CutPointFlags& cut) {
  const SimulationSize size = simulationSize(setup, point, options);
  const QString flags = QString("--speed = %1 rpm and --revolutions = %2 (%3 teeth, %4 steps per tooth period)")
                            .arg(cut.speed_rpm)
                            .arg(options.revolutions)
                            .arg(setup.teeth)
                            .arg(size.steps_per_tooth_period);
  if (size.steps > kMaxSimulationSteps)
    throw CliError(QString("%1: %2 integration steps, at most %3: raise --speed or lower --revolutions")
                       .arg(flags)
                       .arg(size.steps, 0, 'g', 3)
                       .arg(kMaxSimulationSteps, 0, 'g', 3),
                   kExitBadInput);
}

}  // namespace

int runSimulateCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Time-domain chatter simulation of one cutting point.");
  parser.addHelpOption();
  parser.addOptions(cutPointOptions());
  parser.addOptions({
      {"revolutions", "Simulated revolutions (default 60; indicators over the last 20).", "N"},
      {"csv", "Write time, displacements, forces and power to this CSV file.", "FILE"},
      {"ssv-amplitude", "Spindle speed variation amplitude ratio a (eq. 12), default 0.", "A"},
      {"ssv-frequency", "Spindle speed variation frequency [Hz] (eq. 12).", "HZ"},
      {"passes", "Regenerative passes remembered by the chip model (1 = seed eq. 7, default).", "K"},
      {"axial-slices", "Axial slices of a helical cutter, 1-720 (default: 2 deg of helix lag per slice, at most 90).",
       "N"},
  });
  const QString path = parseSubcommand(parser, arguments);
  SimulationOptions options;
  options.revolutions = integerOption(parser, "revolutions", 21, 100000).value_or(60);
  options.ssv.amplitude_ratio = numberOption(parser, "ssv-amplitude", 0.0, 0.9).value_or(0.0);
  options.ssv.frequency_hz = numberOption(parser, "ssv-frequency", 0.0, 1e5).value_or(0.0);
  options.regenerative_passes = integerOption(parser, "passes", 1, kMaxRegenerativePasses).value_or(1);
  options.axial_slices = integerOption(parser, "axial-slices", 1, kMaxAxialSlices).value_or(0);

  const Project project = OutputPaths().outputOption(parser, "csv").loadProject(path);
  const CutPointFlags cut = readCutPoint(parser, project.operating_point);
  const QString& tool = cut.tool;
  const double speed_rpm = cut.speed_rpm, depth_mm = cut.depth_mm, feed_mm = cut.feed_mm_per_tooth;
  requireFittedModes(requireTool(project, tool), "the time-domain simulation");
  const MillingSetup setup = project.setupFor(tool);
  const OperatingPoint point{rpmToRevPerS(speed_rpm), depth_mm * 1e-3, feed_mm * 1e-3};
  checkSimulationSize(setup, point, options, cut);
  // Without --csv only the indicators are printed: keep a sparse trace, not every step.
  if (!parser.isSet("csv"))
    options.record_every =
        static_cast<int>(std::max(1.0, std::ceil(simulationSize(setup, point, options).steps / 1e4)));
  const SimulationResult result = simulateMilling(setup, point, options);
  if (parser.isSet("csv")) writeCsv(parser.value("csv"), result.trace);

  const ChatterIndicators& ind = result.indicators;
  QJsonValue suggested;
  if (ind.chatter_by_eta && ind.chatter_frequency_hz) {
    double max_rev = std::numeric_limits<double>::infinity();
    if (project.machine && project.machine->max_spindle_rpm) max_rev = rpmToRevPerS(*project.machine->max_spindle_rpm);
    if (const auto s = smithTlustySpeed(*ind.chatter_frequency_hz, setup.teeth, point.spindle_rev_per_s, 0.0, max_rev))
      suggested = revPerSToRpm(*s);
  }
  QJsonObject out{
      {"tool", tool},
      {"eta", ind.eta},
      {"chip_ratio", ind.chip_ratio},
      {"chatter", ind.chatter_by_eta},
      {"chatter_frequency_Hz",
       ind.chatter_by_eta && ind.chatter_frequency_hz ? QJsonValue(*ind.chatter_frequency_hz) : QJsonValue()},
      {"tooth_passing_Hz", ind.tooth_passing_hz},
      {"peak_force_N", ind.peak_force_n},
      {"peak_power_W", ind.peak_power_w},
      {"suggested_speed_rpm", suggested},
      {"A_chatter", ind.a_chatter},
      {"A_toothpass", ind.a_toothpass},
      {"chip_ratio_chatter", ind.chatter_by_chip_ratio},
      {"steps_per_tooth_period", result.steps_per_tooth_period},
      {"diverged", result.diverged},
      {"simulated_revolutions", result.simulated_revolutions},
      {"axial_slices", simulationAxialSlices(setup, point.axial_depth_m, options.axial_slices)},
      {"cutter", cutterJson(setup)},
      {"cutting_data", cuttingDataJson(setup)}};
  if (project.machine)  // of P_av at the speed (torque-limited below the base speed)
    out.insert("power_fraction", ind.peak_power_w / availablePowerW(project.machine, speed_rpm));
  printJson(out);
  return kExitOk;
}

}  // namespace mx::app
