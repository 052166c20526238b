#include "services/learning_database.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QVariant>
#include <atomic>
#include <stdexcept>

namespace mx::app {

namespace {

std::atomic<quint64> g_connection_counter{0};

const char* const kSchema[] = {
    "CREATE TABLE learning_entry ("
    " id INTEGER PRIMARY KEY AUTOINCREMENT,"
    " time_utc TEXT NOT NULL,"
    " source TEXT NOT NULL CHECK (source IN ('operator', 'automatic', 'rule', 'feedback')),"
    " tool_id TEXT NOT NULL CHECK (tool_id <> ''),"
    " tool_diameter_mm REAL NOT NULL CHECK (tool_diameter_mm > 0),"
    " tool_teeth INTEGER NOT NULL CHECK (tool_teeth >= 1),"
    " material TEXT NOT NULL CHECK (material <> ''),"
    " spindle_power_w REAL NOT NULL,"
    " max_spindle_rpm REAL,"
    " speed_rpm REAL NOT NULL,"
    " depth_mm REAL NOT NULL,"
    " feed_mm_per_tooth REAL NOT NULL,"
    " mrr_cm3_s REAL,"
    " objectives_json TEXT NOT NULL CHECK (json_valid(objectives_json)),"
    " weight_count INTEGER NOT NULL CHECK (weight_count >= 1),"
    " checksum TEXT NOT NULL)",
    "CREATE TABLE learning_weight ("
    " entry_id INTEGER NOT NULL REFERENCES learning_entry(id) ON DELETE CASCADE,"
    " position INTEGER NOT NULL CHECK (position >= 0),"
    " value REAL NOT NULL,"
    " PRIMARY KEY (entry_id, position)) WITHOUT ROWID",
    "CREATE INDEX learning_entry_tool ON learning_entry(tool_id, time_utc)",
    "CREATE INDEX learning_entry_material ON learning_entry(material, time_utc)",
    "CREATE INDEX learning_entry_mrr ON learning_entry(mrr_cm3_s)",
    "CREATE INDEX learning_entry_time ON learning_entry(time_utc)",
};

const char* const kEntryColumns =
    "id, time_utc, source, tool_id, tool_diameter_mm, tool_teeth, material, spindle_power_w, max_spindle_rpm,"
    " speed_rpm, depth_mm, feed_mm_per_tooth, objectives_json, weight_count, checksum";

QString num(double v) {
  return QString::number(v, 'g', 17);
}

// SHA-256 over every stored field of a record, in a fixed text form (doubles with 17 digits, which
// round-trip exactly through SQLite REAL).
QString checksumOf(const LearningRecord& r, const QString& timeText, const QString& objectivesJson) {
  QStringList weights;
  for (double w : r.weights) weights << num(w);
  const QStringList fields{timeText,
                           learningSourceName(r.source),
                           r.tool.id,
                           num(r.tool.diameter_mm),
                           QString::number(r.tool.teeth),
                           r.material,
                           num(r.machine.spindle_power_W),
                           r.machine.max_spindle_rpm ? num(*r.machine.max_spindle_rpm) : QStringLiteral("null"),
                           num(r.q.speed_rpm),
                           num(r.q.depth_mm),
                           num(r.q.feed_mm_per_tooth),
                           weights.join(','),
                           objectivesJson};
  return QString::fromLatin1(
      QCryptographicHash::hash(fields.join(QChar(0x1f)).toUtf8(), QCryptographicHash::Sha256).toHex());
}

QVariant nullableDouble(const std::optional<double>& value) {
  return value ? QVariant(*value) : QVariant(QMetaType(QMetaType::Double));
}

}  // namespace

QString LearningDatabase::defaultPath() {
  // The GUI's AppDataLocation ("<GenericData>/MillExpert/MillExpert"), spelled out so that
  // millexpert-cli (another application name) uses the same file; no global state is touched.
  const QString data = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation);
  return QDir(data).filePath("MillExpert/MillExpert/learning.sqlite");
}

LearningDatabase::LearningDatabase(const QString& path, OpenMode mode) : path_(path) {
  if (path_.isEmpty()) throw LearningDatabaseError(path_, "no file name given");
  connection_ = QString("mx_learning_%1").arg(++g_connection_counter);
  try {
    open(mode);
    configure();
    migrate();
  } catch (...) {
    closeConnection();
    throw;
  }
}

LearningDatabase::~LearningDatabase() {
  closeConnection();
}

void LearningDatabase::closeConnection() {
  {
    QSqlDatabase db = QSqlDatabase::database(connection_, false);
    if (db.isOpen()) db.close();
  }
  if (QSqlDatabase::contains(connection_)) QSqlDatabase::removeDatabase(connection_);
}

void LearningDatabase::fail(const QString& what) const {
  throw LearningDatabaseError(path_, what);
}

void LearningDatabase::open(OpenMode mode) {
  const QFileInfo info(path_);
  if (info.exists() && !info.isFile()) fail("not a regular file");
  if (!info.exists()) {
    if (mode == OpenMode::ExistingOnly) fail("no such file");
    if (path_ == defaultPath() && !QDir().mkpath(info.absolutePath()))
      fail(QString("cannot create the folder '%1'").arg(info.absolutePath()));
  }
  QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", connection_);
  if (!db.isValid()) fail("the Qt SQLite driver (QSQLITE, package libqt6sql6-sqlite) is not available");
  db.setDatabaseName(path_);
  db.setConnectOptions("QSQLITE_BUSY_TIMEOUT=10000");
  if (!db.open()) fail(QString("cannot open: %1").arg(db.lastError().text()));
}

QSqlQuery LearningDatabase::run(const QString& sql, const QList<QVariant>& binds) const {
  QSqlQuery query(QSqlDatabase::database(connection_, false));
  query.setForwardOnly(true);
  const auto check = [&](bool ok) {
    if (ok) return;
    const QSqlError e = query.lastError();  // SQLite's own text ("file is not a database") when there is one
    fail(QString("%1 (in: %2)").arg(e.databaseText().isEmpty() ? e.text() : e.databaseText(), sql.left(60)));
  };
  check(query.prepare(sql));
  for (const QVariant& b : binds) query.addBindValue(b);
  check(query.exec());
  return query;
}

QVariant LearningDatabase::scalar(const QString& sql) const {
  QSqlQuery query = run(sql);
  if (!query.next()) fail(QString("no result (in: %1)").arg(sql));
  return query.value(0);
}

void LearningDatabase::configure() {
  // Reading the header first turns a corrupt or foreign file into "file is not a database".
  scalar("PRAGMA user_version");
  const QString journal = scalar("PRAGMA journal_mode = WAL").toString();
  if (journal.compare("wal", Qt::CaseInsensitive) != 0)
    fail(QString("cannot switch to WAL journal mode (got '%1')").arg(journal));
  run("PRAGMA synchronous = FULL");
  run("PRAGMA foreign_keys = ON");
}

void LearningDatabase::migrate() {
  run("BEGIN IMMEDIATE");  // serialises concurrent first openings of a new file
  try {
    const int version = scalar("PRAGMA user_version").toInt();
    if (version == 0) {
      if (scalar("SELECT COUNT(*) FROM sqlite_master").toLongLong() != 0)
        fail("not a MillExpert learning database (an SQLite file with other tables)");
      for (const char* statement : kSchema) run(QString::fromLatin1(statement));
      run(QString("PRAGMA application_id = %1").arg(kApplicationId));
      run(QString("PRAGMA user_version = %1").arg(kSchemaVersion));
    } else if (version > kSchemaVersion) {
      fail(QString("schema version %1 was written by a newer MillExpert (this build reads up to %2)")
               .arg(version)
               .arg(kSchemaVersion));
    }
    if (scalar("PRAGMA application_id").toInt() != kApplicationId)
      fail("not a MillExpert learning database (foreign application_id)");
    run("COMMIT");
  } catch (...) {
    QSqlQuery(QSqlDatabase::database(connection_, false)).exec("ROLLBACK");
    throw;
  }
}

int LearningDatabase::schemaVersion() const {
  return scalar("PRAGMA user_version").toInt();
}

QString LearningDatabase::journalMode() const {
  return scalar("PRAGMA journal_mode").toString();
}

qint64 LearningDatabase::count() const {
  return scalar("SELECT COUNT(*) FROM learning_entry").toLongLong();
}

qint64 LearningDatabase::insert(const LearningRecord& input) {
  try {
    validateLearningRecord(input);
  } catch (const std::invalid_argument& e) {
    fail(QString("invalid record: %1").arg(e.what()));
  }
  LearningRecord r = input;
  if (!r.time.isValid()) r.time = QDateTime::currentDateTimeUtc();
  const QString timeText = learningTimeText(r.time);
  const QString objectivesJson = QString::fromUtf8(QJsonDocument(r.objectives).toJson(QJsonDocument::Compact));
  const QJsonValue mrr = r.objectives.value("mrr_cm3_s");
  const QVariant mrrValue = mrr.isDouble() ? QVariant(mrr.toDouble()) : QVariant(QMetaType(QMetaType::Double));

  run("BEGIN IMMEDIATE");
  try {
    const QSqlQuery entry =
        run("INSERT INTO learning_entry (time_utc, source, tool_id, tool_diameter_mm, tool_teeth, material,"
            " spindle_power_w, max_spindle_rpm, speed_rpm, depth_mm, feed_mm_per_tooth, mrr_cm3_s, objectives_json,"
            " weight_count, checksum) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
            {timeText, learningSourceName(r.source), r.tool.id, r.tool.diameter_mm, r.tool.teeth, r.material,
             r.machine.spindle_power_W, nullableDouble(r.machine.max_spindle_rpm), r.q.speed_rpm, r.q.depth_mm,
             r.q.feed_mm_per_tooth, mrrValue, objectivesJson, static_cast<qlonglong>(r.weights.size()),
             checksumOf(r, timeText, objectivesJson)});
    const qint64 id = entry.lastInsertId().toLongLong();
    for (std::size_t i = 0; i < r.weights.size(); ++i)
      run("INSERT INTO learning_weight (entry_id, position, value) VALUES (?, ?, ?)",
          {id, static_cast<qlonglong>(i), r.weights[i]});
    run("COMMIT");
    return id;
  } catch (...) {
    QSqlQuery(QSqlDatabase::database(connection_, false)).exec("ROLLBACK");
    throw;
  }
}

std::vector<LearningRecord> LearningDatabase::select(const QString& where, const QList<QVariant>& binds, int limit,
                                                     QStringList* problems) const {
  QList<QVariant> all = binds;
  all << (limit > 0 ? limit : -1);
  QSqlQuery rows = run(QString("SELECT %1 FROM learning_entry %2 ORDER BY time_utc DESC, id DESC LIMIT ?")
                           .arg(QLatin1String(kEntryColumns), where.isEmpty() ? QString() : "WHERE " + where),
                       all);
  std::vector<LearningRecord> out;
  while (rows.next()) {
    LearningRecord r;
    r.id = rows.value(0).toLongLong();
    const QString timeText = rows.value(1).toString();
    r.time = QDateTime::fromString(timeText, Qt::ISODateWithMs).toUTC();
    try {
      r.source = parseLearningSource(rows.value(2).toString());
    } catch (const std::invalid_argument& e) {
      fail(QString("entry %1: %2").arg(r.id).arg(e.what()));
    }
    r.tool = {rows.value(3).toString(), rows.value(4).toDouble(), rows.value(5).toInt()};
    r.material = rows.value(6).toString();
    r.machine.spindle_power_W = rows.value(7).toDouble();
    if (!rows.value(8).isNull()) r.machine.max_spindle_rpm = rows.value(8).toDouble();
    r.q = {rows.value(9).toDouble(), rows.value(10).toDouble(), rows.value(11).toDouble()};
    const QString objectivesJson = rows.value(12).toString();
    r.objectives = QJsonDocument::fromJson(objectivesJson.toUtf8()).object();
    QSqlQuery weights = run("SELECT value FROM learning_weight WHERE entry_id = ? ORDER BY position", {r.id});
    while (weights.next()) r.weights.push_back(weights.value(0).toDouble());
    if (problems != nullptr) {
      if (static_cast<qint64>(r.weights.size()) != rows.value(13).toLongLong())
        *problems << QString("entry %1: %2 of %3 weights").arg(r.id).arg(r.weights.size()).arg(rows.value(13).toInt());
      if (checksumOf(r, timeText, objectivesJson) != rows.value(14).toString())
        *problems << QString("entry %1: checksum mismatch").arg(r.id);
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<LearningRecord> LearningDatabase::history(const LearningHistoryQuery& query) const {
  QStringList where;
  QList<QVariant> binds;
  if (query.tool) {
    where << "tool_id = ?";
    binds << *query.tool;
  }
  if (query.material) {
    where << "material = ?";
    binds << *query.material;
  }
  return select(where.join(" AND "), binds, query.limit);
}

std::vector<LearningRecord> LearningDatabase::withMrrIn(double lo_cm3_s, double hi_cm3_s, int limit) const {
  if (!(lo_cm3_s <= hi_cm3_s)) fail(QString("MRR range [%1, %2] is empty").arg(lo_cm3_s).arg(hi_cm3_s));
  return select("mrr_cm3_s BETWEEN ? AND ?", {lo_cm3_s, hi_cm3_s}, limit);
}

std::optional<WeightSuggestion> LearningDatabase::suggestInitialWeights(const JobFeatures& job, int k) const {
  const std::vector<LearningRecord> candidates =
      select("material = ? AND weight_count = ?", {job.material, static_cast<qlonglong>(job.weight_count)}, 0);
  try {
    return suggestWeights(candidates, job, k);
  } catch (const std::invalid_argument& e) {
    fail(e.what());
  }
}

LearningConsistency LearningDatabase::checkConsistency() const {
  LearningConsistency c;
  QStringList integrity;
  for (QSqlQuery q = run("PRAGMA integrity_check"); q.next();) integrity << q.value(0).toString();
  c.integrity = integrity.join("; ");
  for (QSqlQuery q = run("PRAGMA foreign_key_check"); q.next();)
    c.problems << QString("foreign key: %1 row %2").arg(q.value(0).toString(), q.value(1).toString());
  c.entries = static_cast<qint64>(select({}, {}, 0, &c.problems).size());
  return c;
}

}  // namespace mx::app
