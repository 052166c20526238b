// millexpert-cli override PROGRAM.nc PROJECT --out OUT.nc [--csv FILE] [--controller adaptive|model-based]
//                                            [--speed RPM]
// Runs a force controller along a G-code part program (part_program_request.h) and writes the
// optimised program: only F and S words and comments change; every changed block carries the reason;
// a header names the project, the controller and the date. --csv: the per-block feed-override table.
// Prints {"program", "out", "csv", "controller", "blocks", "feed_moves", "changed_blocks",
//   "max_predicted_force_N", "warnings": [{"line", "column", "text", "message"}]} plus, with the
//   adaptive controller, "closed_loop": {"max_force_N", "settling_time_s", "Jc", "completed"}.
// Exit 2: bad project, flags or program (unreadable, a feed move without a spindle speed); exit 1:
// the controller failed.
#include <QDateTime>
#include <QFileInfo>
#include <QJsonArray>
#include <cmath>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "cli/output_paths.h"
#include "core/invalid_input.h"
#include "gcode/gcode_reader.h"
#include "services/part_program_request.h"

namespace mx::app {

int runOverrideCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Optimise the feeds of a G-code part program with a force controller.");
  parser.addHelpOption();
  parser.addPositionalArgument("PROGRAM", "The G-code part program (.nc, at most 16 MB).");
  parser.addPositionalArgument("PROJECT", "The .mxproj project file.");
  parser.addOptions({
      {"out", "Write the optimised program to FILE (required).", "FILE"},
      {"csv", "Write the per-block feed-override table to FILE.", "FILE"},
      {"controller", "adaptive or model-based (default: the project's part_program.controller).", "NAME"},
      {"speed", "Spindle speed [rpm] of the expert system: every S word becomes it.", "RPM"},
  });
  parseArguments(parser, arguments);
  const QStringList positional = parser.positionalArguments();
  if (positional.size() != 2)
    throw CliError(QString("expected PROGRAM.nc and PROJECT, got %1 argument(s)").arg(positional.size()),
                   kExitBadInput);
  const QString out_path = requiredOption(parser, "out");
  const std::optional<double> speed = numberOption(parser, "speed", 1e-3, 1e5);
  const Project project = OutputPaths()
                              .input("PROGRAM", positional[0])
                              .output("--out", out_path)
                              .outputOption(parser, "csv")
                              .loadProject(positional[1]);
  const OverrideRequest request = overrideRequestFromProject(project, parser.value("controller"), speed);

  GcodeProgram program;
  try {
    program = GcodeReader::readFile(positional[0].toStdString());
  } catch (const std::exception& e) {
    throw CliError(QString("%1: %2").arg(positional[0], e.what()), kExitBadInput);
  }
  OverrideOutcome outcome;
  try {
    outcome = runOverride(request, program);
  } catch (const InvalidInput& e) {
    throw CliError(QString("override: %1").arg(e.what()), kExitBadInput);
  } catch (const std::exception& e) {
    throw CliError(QString("override: the controller failed: %1").arg(e.what()), kExitComputationFailed);
  }
  const PartProgramOverrideResult& r = outcome.result;
  const GcodeHeader header{QFileInfo(positional[1]).fileName().toStdString(), outcome.controller.toStdString(),
                           QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString()};
  const std::string text = r.writeProgram(header);
  writeTextFileAtomically("--out", out_path, [&](QTextStream& s) { s << QString::fromStdString(text); });
  if (parser.isSet("csv"))
    writeTextFileAtomically("--csv", parser.value("csv"),
                            [&](QTextStream& s) { s << QString::fromStdString(r.csv()); });

  QJsonArray warnings;
  for (const GcodeWarning& w : r.warnings)
    warnings.append(QJsonObject{{"line", w.line},
                                {"column", static_cast<qint64>(w.column)},
                                {"text", QString::fromStdString(w.text)},
                                {"message", QString::fromStdString(w.message)}});
  double max_force = 0.0;
  for (const FeedOverrideRow& row : r.rows)
    if (std::isfinite(row.predicted_force_N)) max_force = std::max(max_force, row.predicted_force_N);
  QJsonObject out{{"program", positional[0]},
                  {"out", out_path},
                  {"csv", parser.isSet("csv") ? QJsonValue(parser.value("csv")) : QJsonValue()},
                  {"controller", outcome.controller},
                  {"blocks", static_cast<qint64>(r.program.blocks.size())},
                  {"feed_moves", static_cast<qint64>(r.rows.size())},
                  {"changed_blocks", static_cast<qint64>(r.changed_blocks)},
                  {"max_predicted_force_N", max_force},
                  {"warnings", warnings}};
  if (outcome.adaptive_metrics) {
    const ClosedLoopMetrics& m = *outcome.adaptive_metrics;
    out.insert("closed_loop", QJsonObject{{"max_force_N", m.max_force_N},
                                          {"settling_time_s", m.settling_time_s},
                                          {"Jc", m.Jc_N_s},
                                          {"completed", m.completed}});
  }
  printJson(out);
  return kExitOk;
}

}  // namespace mx::app
