// millexpert-cli history PROJECT [--tool ID] [--db FILE] [--limit N] [--all-materials] [--add-json JSON]
// Rule 14 learning database: the programmed points of the project's material (all materials with
// --all-materials), newest first, optionally of one tool. Prints
//   {"entries": [{"time","tool","material","weights","q":{"speed_rpm","depth_mm","feed_mm_per_tooth"},
//                 "objectives","source"}...]}.
// --add-json '{"tool":"R1","weights":[...],"q":{...},"objectives":{...},"source":"operator"[,"time"]}'
// first records one point (tool features, material and machine from the project) in one transaction.
// The database defaults to learning.sqlite in the MillExpert application-data folder; a missing
// default database reads as empty. Exit 2: missing --db file (except with --add-json, which creates
// it), corrupt or foreign database file (the message names it), bad record or project.
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "cli/output_paths.h"
#include "document/project.h"
#include "document/shortened_text.h"
#include "services/learning_database.h"

namespace mx::app {

namespace {

double requiredNumber(const QJsonObject& object, const QString& key, const QString& path) {
  const QJsonValue v = object.value(key);
  if (!v.isDouble()) throw CliError(QString("--add-json: %1%2 must be a number").arg(path, key), kExitBadInput);
  return v.toDouble();
}

LearningRecord recordFromJson(const QString& text, const Project& project) {
  QJsonParseError error{};
  const QJsonDocument doc = QJsonDocument::fromJson(text.toUtf8(), &error);
  if (!doc.isObject())
    throw CliError(QString("--add-json: not a JSON object (%1)").arg(error.errorString()), kExitBadInput);
  const QJsonObject o = doc.object();
  LearningRecord r;
  const ToolSpec* tool = project.findTool(o.value("tool").toString());
  if (tool == nullptr)
    throw CliError(QString("--add-json: tool %1 not found in the project").arg(quoted(o.value("tool").toString())),
                   kExitBadInput);
  if (!project.material) throw CliError("--add-json: the project has no material section", kExitBadInput);
  const MachineSpec& machine = project.requireMachine();
  r.tool = {tool->id, tool->diameter_mm, tool->teeth};
  r.material = project.material->name;
  r.machine = {machine.name, machine.spindle_power_W, machine.max_spindle_rpm};
  if (!o.value("weights").isArray()) throw CliError("--add-json: weights must be an array", kExitBadInput);
  for (const QJsonValue w : o.value("weights").toArray()) {
    if (!w.isDouble()) throw CliError("--add-json: weights must be numbers", kExitBadInput);
    r.weights.push_back(w.toDouble());
  }
  const QJsonObject q = o.value("q").toObject();
  r.q = {requiredNumber(q, "speed_rpm", "q."), requiredNumber(q, "depth_mm", "q."),
         requiredNumber(q, "feed_mm_per_tooth", "q.")};
  r.objectives = o.value("objectives").toObject();
  try {
    r.source = parseLearningSource(o.value("source").toString("operator"));
  } catch (const std::invalid_argument& e) {
    throw CliError(QString("--add-json: %1").arg(e.what()), kExitBadInput);
  }
  if (o.contains("time")) {
    r.time = QDateTime::fromString(o.value("time").toString(), Qt::ISODateWithMs);
    if (!r.time.isValid()) throw CliError("--add-json: time must be ISO 8601", kExitBadInput);
  }
  return r;
}

}  // namespace

int runHistoryCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Programmed points of the Rule 14 learning database, newest first.");
  parser.addHelpOption();
  parser.addOptions({
      {"tool", "Only the entries of this tool id.", "ID"},
      {"db", "The learning database (default: learning.sqlite in the application-data folder).", "FILE"},
      {"limit", "At most N entries (default 100).", "N"},
      {"all-materials", "Entries of every material, not only the project's."},
      {"add-json", "First record one point: {tool, weights, q, objectives, source[, time]}.", "JSON"},
  });
  const QString projectPath = parseSubcommand(parser, arguments);
  const int limit = integerOption(parser, "limit", 1, 1000000).value_or(100);
  OutputPaths files;  // the database is written only with --add-json
  if (parser.isSet("add-json")) files.outputOption(parser, "db");
  const Project project = files.loadProject(projectPath);
  const bool add = parser.isSet("add-json");
  const std::optional<LearningRecord> record =
      add ? std::optional<LearningRecord>(recordFromJson(parser.value("add-json"), project)) : std::nullopt;

  const QString dbPath = parser.isSet("db") ? parser.value("db") : LearningDatabase::defaultPath();
  LearningHistoryQuery query;
  query.limit = limit;
  if (parser.isSet("tool")) query.tool = parser.value("tool");
  if (!parser.isSet("all-materials") && project.material) query.material = project.material->name;

  QJsonArray entries;
  try {
    if (add || parser.isSet("db") || QFileInfo::exists(dbPath)) {
      LearningDatabase db(dbPath,
                          add ? LearningDatabase::OpenMode::CreateIfMissing : LearningDatabase::OpenMode::ExistingOnly);
      if (record) db.insert(*record);
      for (const LearningRecord& r : db.history(query)) entries.append(learningEntryJson(r));
    }
  } catch (const LearningDatabaseError& e) {
    throw CliError(QString::fromStdString(e.what()), kExitBadInput);
  }
  printJson(QJsonObject{{"entries", entries}});
  return kExitOk;
}

}  // namespace mx::app
