// millexpert-cli sdnrp PROJECT --ra UM [--seconds 15] [--csv FILE] [--no-disturbance] [--seed N] [--no-control]
// Cus & Zuperl (2008): the SDNRP loop that holds the cutting force at F_d = K1(Ra) so that the produced
// roughness meets the desired Ra (engine/sdnrp; the project's "sdnrp" section, sdnrp_request.h).
// Prints {"Ra_desired","Fd_N","F_final_N","feed_final_mm_min","speed_final_rpm","Ra_produced"} (um, N,
// mm/min, rpm) plus "feed_saturated" (F_d not reachable within the feed limits), "disturbance",
// "seed" and "seconds". --csv: the six console signals of the paper's section 5 every 10 ms.
// --no-control: the paper's run without SDNRP (Figs 12 and 14): feed and speed held at the loop's
// initial ones, same plant, drives and disturbance. Both runs also print "control", the held or starting
// "initial_feed_mm_min" and "initial_speed_rpm", and the spread of the measured force and of its Ra,
// {"min","max","mean","std","rms_error"} (rms_error about F_d and Ra_desired), over the whole run
// ("F_spread_N", "Ra_spread_um") and over the final second ("F_final_spread_N", "Ra_final_spread_um").
// Exit 2: bad project or flags (Ra outside 0.25..2.5 um); exit 1: the simulation failed.
#include <QJsonObject>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "cli/output_paths.h"
#include "core/invalid_input.h"
#include "services/sdnrp_request.h"

namespace mx::app {

namespace {

void writeSignals(const QString& path, const SdnrpResult& r) {
  writeTextFileAtomically("--csv", path, [&](QTextStream& out) {
    out << "t_s,Ra_um,Ra_dynamic_um,F_N,F_dynamic_N,feed_mm_min,speed_rpm,feed_command_mm_min,speed_command_rpm\n";
    for (const SdnrpSample& s : r.samples)
      out << s.t_s << ',' << s.ra_m * 1e6 << ',' << s.ra_dynamic_m * 1e6 << ',' << s.force_N << ',' << s.force_dynamic_N
          << ',' << s.feed_m_per_s * 60e3 << ',' << s.speed_rev_per_s * 60.0 << ',' << s.feed_command_m_per_s * 60e3
          << ',' << s.speed_command_rev_per_s * 60.0 << '\n';
  });
}

QJsonObject spreadJson(const SdnrpSpread& s, double scale) {
  return {{"min", s.min * scale},
          {"max", s.max * scale},
          {"mean", s.mean * scale},
          {"std", s.std * scale},
          {"rms_error", s.rms_error * scale}};
}

}  // namespace

int runSdnrpCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Cus & Zuperl SDNRP: force and surface-roughness control.");
  parser.addHelpOption();
  parser.addOptions({
      {"ra", "Desired surface roughness Ra [um], 0.25..2.5. Default: the project's sdnrp.ra_um.", "UM"},
      {"seconds", "Simulated time [s] (default 15, the paper's Table 2).", "S"},
      {"csv", "Write the six signals (every 10 ms) to FILE.", "FILE"},
      {"no-disturbance", "Switch the unmodelled-dynamics disturbance off."},
      {"seed", "Seed of the disturbance generator.", "N"},
      {"no-control", "Run without SDNRP: feed and speed held at the initial ones (the paper's Figs 12 and 14)."},
  });
  const QString path = parseSubcommand(parser, arguments);
  const std::optional<double> ra = numberOption(parser, "ra", 0.25, 2.5);
  const std::optional<double> seconds = numberOption(parser, "seconds", 0.1, 600.0);
  const std::optional<int> seed = integerOption(parser, "seed", 0, 2147483647);
  const Project project = OutputPaths().outputOption(parser, "csv").loadProject(path);
  SdnrpSettings s = sdnrpSettingsFromProject(project);
  if (ra) s.ra_desired_m = *ra * 1e-6;
  if (seconds) s.duration_s = *seconds;
  if (seed) s.disturbance.seed = static_cast<std::uint64_t>(*seed);
  if (parser.isSet("no-disturbance")) s.disturbance.enabled = false;
  if (parser.isSet("no-control")) s.control = false;
  SdnrpResult r;
  try {
    r = SdnrpSimulator(s).run();
  } catch (const InvalidInput& e) {
    throw CliError(QString("sdnrp: %1").arg(e.what()), kExitBadInput);
  } catch (const std::exception& e) {
    throw CliError(QString("sdnrp: the simulation failed: %1").arg(e.what()), kExitComputationFailed);
  }
  if (parser.isSet("csv")) writeSignals(parser.value("csv"), r);
  printJson({{"Ra_desired", r.ra_desired_m * 1e6},
             {"Fd_N", r.fd_N},
             {"F_final_N", r.f_final_N},
             {"feed_final_mm_min", r.feed_final_m_per_s * 60e3},
             {"speed_final_rpm", r.speed_final_rev_per_s * 60.0},
             {"Ra_produced", r.ra_produced_m * 1e6},
             {"feed_saturated", r.feed_saturated},
             {"disturbance", s.disturbance.enabled},
             {"seed", static_cast<qint64>(s.disturbance.seed)},
             {"seconds", s.duration_s},
             {"control", r.control},
             {"initial_feed_mm_min", r.initial_feed_m_per_s * 60e3},
             {"initial_speed_rpm", r.initial_speed_rev_per_s * 60.0},
             {"F_spread_N", spreadJson(r.force_run, 1.0)},
             {"Ra_spread_um", spreadJson(r.ra_run, 1e6)},
             {"F_final_spread_N", spreadJson(r.force_final, 1.0)},
             {"Ra_final_spread_um", spreadJson(r.ra_final, 1e6)}});
  return kExitOk;
}

}  // namespace mx::app
