// millexpert-cli override PROGRAM PROJECT --out OUT [--csv FILE] [--controller adaptive|model-based]
//                                      [--speed RPM] [--dialect iso|heidenhain|sinumerik|linuxcnc]
//                                      [--afc AFC.TAB [--afc-tool TOOL.TAB] [--afc-overload M|S|F|E|L|-]]
// Runs a force controller along a part program (part_program_request.h) and writes the optimised
// program in the program's own dialect (engine/gcode/gcode_dialect.h; detected unless --dialect names
// it): only F and S words and comments change; every changed block carries the reason; a header names
// the project, the controller and the date. --csv: the per-block feed-override table. --afc: the
// Heidenhain AFC.TAB row for the tool, taught at the project's operating_point (afc_request.h);
// --afc-tool: the tool-table excerpt with its AFC-LOAD.
// Prints {"program", "out", "csv", "controller", "dialect", "dialect_source", "blocks", "feed_moves",
//   "changed_blocks", "max_predicted_force_N", "warnings": [{"line", "column", "text", "message"}]}
//   plus, with the adaptive controller, "closed_loop": {"max_force_N", "settling_time_s", "Jc",
//   "completed"}, and with --afc, "afc": {"table", "tool_table", "name", "tool", "tool_number",
//   "afc_load_kW", "FMIN", "FMAX", "FIDL", "FENT", "OVLD", "POUT", "SENS", "PLC", "fmax_limited_by",
//   "point": {"speed_rpm", "depth_mm", "feed_mm_per_tooth"}}.
// Exit 2: bad project, flags or program (unreadable, undetectable dialect, a line that cannot be split
// into words, a feed move without a spindle speed); exit 1: the controller failed.
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
#include "services/afc_request.h"
#include "services/part_program_request.h"

namespace mx::app {
namespace {

QJsonObject afcJson(const AfcOutcome& afc, const QString& table, const QString& tool_table) {
  const AfcSetting& s = afc.teach_in.setting;
  return QJsonObject{{"table", table},
                     {"tool_table", tool_table.isEmpty() ? QJsonValue() : QJsonValue(tool_table)},
                     {"name", QString::fromStdString(s.name)},
                     {"tool", afc.tool},
                     {"tool_number", afc.tool_number},
                     {"afc_load_kW", afc.teach_in.afc_load_W * 1e-3},
                     {"FMIN", s.fmin_percent},
                     {"FMAX", s.fmax_percent},
                     {"FIDL", s.fidl_percent},
                     {"FENT", s.fent_percent},
                     {"OVLD", QString(QChar(s.ovld))},
                     {"POUT", s.pout_percent},
                     {"SENS", s.sens_percent},
                     {"PLC", s.plc},
                     {"fmax_limited_by", QString::fromStdString(afc.teach_in.fmax_limited_by)},
                     {"point", QJsonObject{{"speed_rpm", afc.point.speed_rpm},
                                           {"depth_mm", afc.point.depth_mm},
                                           {"feed_mm_per_tooth", afc.point.feed_mm_per_tooth}}}};
}

}  // namespace

int runOverrideCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Optimise the feeds of a part program (ISO/Fanuc, Heidenhain Klartext, Siemens Sinumerik or LinuxCNC) with a "
      "force controller; the program is written back in its own dialect.");
  parser.addHelpOption();
  parser.addPositionalArgument("PROGRAM", "The part program (.nc, .h, .mpf, .ngc, ...; at most 16 MB).");
  parser.addPositionalArgument("PROJECT", "The .mxproj project file.");
  parser.addOptions({
      {"out", "Write the optimised program to FILE (required).", "FILE"},
      {"csv", "Write the per-block feed-override table to FILE.", "FILE"},
      {"controller", "adaptive or model-based (default: the project's part_program.controller).", "NAME"},
      {"speed", "Spindle speed [rpm] of the expert system: every S word becomes it.", "RPM"},
      {"dialect", "The program's controller dialect: iso, heidenhain, sinumerik or linuxcnc (default: detected).",
       "NAME"},
      {"afc", "Heidenhain: write the AFC.TAB row for the tool, taught at the project's operating_point.", "FILE"},
      {"afc-tool", "Heidenhain: write the tool-table excerpt (T, NAME, AFC, AFC-LOAD [kW]) to FILE.", "FILE"},
      {"afc-overload", "AFC's reaction to an overload (OVLD): M, S, F, E, L or - (default E).", "CODE"},
  });
  parseArguments(parser, arguments);
  const QStringList positional = parser.positionalArguments();
  if (positional.size() != 2)
    throw CliError(QString("expected PROGRAM.nc and PROJECT, got %1 argument(s)").arg(positional.size()),
                   kExitBadInput);
  const QString out_path = requiredOption(parser, "out");
  std::optional<GcodeDialect> dialect;
  if (parser.isSet("dialect")) {
    dialect = dialectFromName(parser.value("dialect").toStdString());
    if (!dialect)
      throw CliError(QString("--dialect = '%1': must be one of %2")
                         .arg(parser.value("dialect"), QString::fromStdString(dialectNames())),
                     kExitBadInput);
  }
  if ((parser.isSet("afc-tool") || parser.isSet("afc-overload")) && !parser.isSet("afc"))
    throw CliError("--afc-tool and --afc-overload go with --afc FILE", kExitBadInput);
  const QString overload = parser.value("afc-overload");
  if (parser.isSet("afc-overload") && (overload.size() != 1 || !QString("MSFEL-").contains(overload)))
    throw CliError(QString("--afc-overload = '%1': must be one of M, S, F, E, L, -").arg(overload), kExitBadInput);
  const std::optional<double> speed = numberOption(parser, "speed", 1e-3, 1e5);
  const Project project = OutputPaths()
                              .input("PROGRAM", positional[0])
                              .output("--out", out_path)
                              .outputOption(parser, "csv")
                              .outputOption(parser, "afc")
                              .outputOption(parser, "afc-tool")
                              .loadProject(positional[1]);
  const OverrideRequest request = overrideRequestFromProject(project, parser.value("controller"), speed);

  GcodeProgram program;
  try {
    program = GcodeReader::readFile(positional[0].toStdString(), dialect);
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
  std::optional<AfcOutcome> afc;
  if (parser.isSet("afc"))
    afc = afcFromProject(project, program, speed, overload.isEmpty() ? 'E' : overload.at(0).toLatin1());
  const PartProgramOverrideResult& r = outcome.result;
  const GcodeHeader header{QFileInfo(positional[1]).fileName().toStdString(), outcome.controller.toStdString(),
                           QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString()};
  const std::string text = r.writeProgram(header);
  writeTextFileAtomically("--out", out_path, [&](QTextStream& s) { s << QString::fromStdString(text); });
  if (parser.isSet("csv"))
    writeTextFileAtomically("--csv", parser.value("csv"),
                            [&](QTextStream& s) { s << QString::fromStdString(r.csv()); });

  if (afc) {
    writeTextFileAtomically("--afc", parser.value("afc"),
                            [&](QTextStream& s) { s << QString::fromStdString(afcTableText(afc->teach_in.setting)); });
    if (parser.isSet("afc-tool"))
      writeTextFileAtomically("--afc-tool", parser.value("afc-tool"), [&](QTextStream& s) {
        s << QString::fromStdString(afcToolTableText(afc->tool_number, afc->tool.toStdString(), afc->teach_in));
      });
  }

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
                  {"dialect", QString::fromStdString(std::string(dialectName(program.dialect.dialect)))},
                  {"dialect_source", dialect ? "named" : (program.dialect.line > 0 ? "detected" : "default")},
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
  if (afc) out.insert("afc", afcJson(*afc, parser.value("afc"), parser.value("afc-tool")));
  printJson(out);
  return kExitOk;
}

}  // namespace mx::app
