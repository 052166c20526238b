// millexpert-cli history PROJECT [--tool ID] [--machine NAME] [--db FILE|URL] [--limit N] [--all-materials]
//                                [--add-json JSON] [--import FILE|URL]
// Rule 14 learning database: the programmed points of the project's material (all materials with
// --all-materials), newest first, optionally of one tool or one machine. Prints
//   {"entries": [{"time","tool","material","machine","weights",
//                 "q":{"speed_rpm","depth_mm","feed_mm_per_tooth"},"objectives","source"}...]}.
// --add-json '{"tool":"R1","weights":[...],"q":{...},"objectives":{...},"source":"operator"[,"time"]}'
// first records one point (tool features, material and machine from the project) in one transaction.
// --import SOURCE first copies every record of another learning database (a machine's own file into
// the shop's server) in one transaction; a record already present (same uid) is not copied again, and
// "imported": {"from", "records", "new"} is added to the output.
// The database is --db, else the user's setting learning/database (a file or a postgresql:// URL),
// else learning.sqlite in the MillExpert application-data folder; a missing default file reads as
// empty. Exit 2: missing --db file (except with --add-json or --import, which create it), a bad URL,
// a server that refuses the connection, a corrupt or foreign database (the message names it), a bad
// record or project.
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
  r.machine = {machine.name, machine.spindle_power_W, machine.max_spindle_rpm};  // name: which machine ran it
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

// Every record of `source`, copied into `db` in one transaction; {"from", "records", "new"}.
QJsonObject importRecords(LearningDatabase& db, const QString& source) {
  const LearningDatabase from(source, LearningDatabase::OpenMode::ExistingOnly);
  const std::vector<LearningRecord> records = from.history({std::nullopt, std::nullopt, std::nullopt, 0});
  const qint64 before = db.count();
  db.insertAll(records);
  return {{"from", from.location()}, {"records", static_cast<qint64>(records.size())}, {"new", db.count() - before}};
}

}  // namespace

int runHistoryCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Programmed points of the Rule 14 learning database, newest first.");
  parser.addHelpOption();
  parser.addOptions({
      {"tool", "Only the entries of this tool id.", "ID"},
      {"machine", "Only the entries of this machine (the project's machine.name when recorded).", "NAME"},
      {"db",
       "The learning database: an SQLite file or postgresql://user@host[:port]/db (the password from PGPASSWORD or "
       "~/.pgpass). Default: the setting learning/database, else learning.sqlite in the application-data folder.",
       "FILE|URL"},
      {"limit", "At most N entries (default 100).", "N"},
      {"all-materials", "Entries of every material, not only the project's."},
      {"add-json", "First record one point: {tool, weights, q, objectives, source[, time]}.", "JSON"},
      {"import", "First copy every record of this learning database (file or URL) in; records present stay once.",
       "FILE|URL"},
  });
  const QString projectPath = parseSubcommand(parser, arguments);
  const int limit = integerOption(parser, "limit", 1, 1000000).value_or(100);
  const bool add = parser.isSet("add-json");
  const bool write = add || parser.isSet("import");
  const QString dbLocation = parser.isSet("db") ? parser.value("db") : LearningDatabase::configuredOrDefault();
  OutputPaths files;  // a database file is written only with --add-json or --import
  if (write && parser.isSet("db") && !isLearningUrl(dbLocation)) files.outputOption(parser, "db");
  const Project project = files.loadProject(projectPath);
  const std::optional<LearningRecord> record =
      add ? std::optional<LearningRecord>(recordFromJson(parser.value("add-json"), project)) : std::nullopt;

  LearningHistoryQuery query;
  query.limit = limit;
  if (parser.isSet("tool")) query.tool = parser.value("tool");
  if (parser.isSet("machine")) query.machine = parser.value("machine");
  if (!parser.isSet("all-materials") && project.material) query.material = project.material->name;

  QJsonObject out;
  QJsonArray entries;
  try {
    const bool missingDefaultFile =
        !write && !parser.isSet("db") && !isLearningUrl(dbLocation) && !QFileInfo::exists(dbLocation);
    if (!missingDefaultFile) {
      LearningDatabase db(
          dbLocation, write ? LearningDatabase::OpenMode::CreateIfMissing : LearningDatabase::OpenMode::ExistingOnly);
      if (parser.isSet("import")) out.insert("imported", importRecords(db, parser.value("import")));
      if (record) db.insert(*record);
      for (const LearningRecord& r : db.history(query)) entries.append(learningEntryJson(r));
    }
  } catch (const LearningDatabaseError& e) {
    throw CliError(QString::fromStdString(e.what()), kExitBadInput);
  }
  out.insert("entries", entries);
  printJson(out);
  return kExitOk;
}

}  // namespace mx::app
