#include "services/learning_database.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QUuid>
#include <QVariant>
#include <array>
#include <atomic>
#include <stdexcept>

#include "services/learning_migrations.h"

namespace mx::app {

namespace {

std::atomic<quint64> g_connection_counter{0};

constexpr std::array<const char*, 18> kEntryColumns{"id",
                                                    "time_utc",
                                                    "source",
                                                    "tool_id",
                                                    "tool_diameter_mm",
                                                    "tool_teeth",
                                                    "material",
                                                    "machine",
                                                    "spindle_power_w",
                                                    "max_spindle_rpm",
                                                    "speed_rpm",
                                                    "depth_mm",
                                                    "feed_mm_per_tooth",
                                                    "objectives_json",
                                                    "weight_count",
                                                    "checksum",
                                                    "record_uid",
                                                    "mrr_cm3_s"};
// The column order of a selected row: kEntryColumns, then the weight's position and value.
enum Column {
  kId,
  kTime,
  kSource,
  kToolId,
  kDiameter,
  kTeeth,
  kMaterial,
  kMachine,
  kPower,
  kMaxRpm,
  kSpeed,
  kDepth,
  kFeed,
  kObjectives,
  kWeightCount,
  kChecksum,
  kUid,
  kMrr,
  kWeightPosition,
  kWeightValue
};

QString columns(const char* prefix) {
  QStringList names;
  for (const char* name : kEntryColumns) names << QString::fromLatin1(prefix) + QString::fromLatin1(name);
  return names.join(", ");
}

QString num(double v) {
  return QString::number(v, 'g', 17);
}

// SHA-256 over every stored field of a record, in a fixed text form (doubles with 17 digits, which
// round-trip exactly through a REAL or DOUBLE PRECISION column). The machine is appended only when the
// record names one, so that the checksums of version-1 rows stay valid after the migration.
QString checksumOf(const LearningRecord& r, const QString& timeText, const QString& objectivesJson) {
  QStringList weights;
  for (double w : r.weights) weights << num(w);
  QStringList fields{timeText,
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
  if (r.machine.name) fields << *r.machine.name;
  return QString::fromLatin1(
      QCryptographicHash::hash(fields.join(QChar(0x1f)).toUtf8(), QCryptographicHash::Sha256).toHex());
}

QVariant nullableDouble(const std::optional<double>& value) {
  return value ? QVariant(*value) : QVariant(QMetaType(QMetaType::Double));
}

QVariant nullableText(const std::optional<QString>& value) {
  return value ? QVariant(*value) : QVariant(QMetaType(QMetaType::QString));
}

QString objectivesText(const QJsonObject& objectives) {
  return QString::fromUtf8(QJsonDocument(objectives).toJson(QJsonDocument::Compact));
}

// A selected entry with the stored fields its check needs.
struct StoredEntry {
  LearningRecord record;
  qint64 weight_count = 0;
  QString checksum, time_text, objectives_text;
};

// The entry fields of a selected row; its weights follow in the rows of the same id.
StoredEntry entryOf(const QSqlQuery& row) {
  StoredEntry e;
  LearningRecord& r = e.record;
  r.id = row.value(kId).toLongLong();
  e.time_text = row.value(kTime).toString();
  r.time = QDateTime::fromString(e.time_text, Qt::ISODateWithMs).toUTC();
  r.source = parseLearningSource(row.value(kSource).toString());
  r.tool = {row.value(kToolId).toString(), row.value(kDiameter).toDouble(), row.value(kTeeth).toInt()};
  r.material = row.value(kMaterial).toString();
  if (!row.value(kMachine).isNull()) r.machine.name = row.value(kMachine).toString();
  r.machine.spindle_power_W = row.value(kPower).toDouble();
  if (!row.value(kMaxRpm).isNull()) r.machine.max_spindle_rpm = row.value(kMaxRpm).toDouble();
  r.q = {row.value(kSpeed).toDouble(), row.value(kDepth).toDouble(), row.value(kFeed).toDouble()};
  e.objectives_text = row.value(kObjectives).toString();
  r.objectives = QJsonDocument::fromJson(e.objectives_text.toUtf8()).object();
  r.uid = row.value(kUid).toString();
  e.weight_count = row.value(kWeightCount).toLongLong();
  e.checksum = row.value(kChecksum).toString();
  return e;
}

void checkEntry(const StoredEntry& e, QStringList* problems) {
  const LearningRecord& r = e.record;
  if (static_cast<qint64>(r.weights.size()) != e.weight_count)
    *problems << QString("entry %1: %2 of %3 weights").arg(r.id).arg(r.weights.size()).arg(e.weight_count);
  if (checksumOf(r, e.time_text, e.objectives_text) != e.checksum)
    *problems << QString("entry %1: checksum mismatch").arg(r.id);
  if (r.uid.isEmpty()) *problems << QString("entry %1: no record_uid").arg(r.id);
}

}  // namespace

QString LearningDatabase::defaultPath() {
  // The GUI's AppDataLocation ("<GenericData>/MillExpert/MillExpert"), spelled out so that
  // millexpert-cli (another application name) uses the same file; no global state is touched.
  const QString data = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation);
  return QDir(data).filePath("MillExpert/MillExpert/learning.sqlite");
}

QString LearningDatabase::configuredOrDefault() {
  const QString configured = configuredLearningDatabase();
  return configured.isEmpty() ? defaultPath() : configured;
}

LearningDatabase::LearningDatabase(const QString& location, OpenMode mode)
    : LearningDatabase(location, mode, latestLearningSchemaVersion()) {}

LearningDatabase::LearningDatabase(const QString& location, OpenMode mode, int target_version)
    : sql_(LearningBackend::Sqlite) {
  try {
    location_ = parseLearningLocation(location);
  } catch (const std::invalid_argument& e) {
    throw LearningDatabaseError(redactedLearningLocation(location), QString::fromStdString(e.what()).section(": ", 1));
  }
  sql_ = LearningSqlDialect(location_.backend);
  if (target_version < 1 || target_version > latestLearningSchemaVersion())
    fail(QString("schema version %1 is outside 1..%2").arg(target_version).arg(latestLearningSchemaVersion()));
  connection_ = QString("mx_learning_%1").arg(++g_connection_counter);
  try {
    open(mode);
    if (sql_.isSqlite()) configureSqlite();
    migrate(target_version);
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
  throw LearningDatabaseError(location_.display(), what);
}

void LearningDatabase::open(OpenMode mode) {
  if (sql_.isSqlite()) {
    const QFileInfo info(location_.file);
    if (info.exists() && !info.isFile()) fail("not a regular file");
    if (!info.exists()) {
      if (mode == OpenMode::ExistingOnly) fail("no such file");
      if (location_.file == defaultPath() && !QDir().mkpath(info.absolutePath()))
        fail(QString("cannot create the folder '%1'").arg(info.absolutePath()));
    }
  }
  QSqlDatabase db = QSqlDatabase::addDatabase(sql_.driver(), connection_);
  if (!db.isValid())
    fail(sql_.isSqlite() ? "the Qt SQLite driver (QSQLITE, package libqt6sql6-sqlite) is not available"
                         : "the Qt PostgreSQL driver (QPSQL, package libqt6sql6-psql) is not available");
  if (sql_.isSqlite()) {
    db.setDatabaseName(location_.file);
    // SQLite's busy handler polls with no queue: with many writers one can wait far longer than the
    // average write (8 writers under ASan: past 10 s). A record waits rather than fails.
    db.setConnectOptions("QSQLITE_BUSY_TIMEOUT=60000");
  } else {
    db.setHostName(location_.host);
    db.setPort(location_.port);
    db.setDatabaseName(location_.database);
    if (!location_.user.isEmpty()) db.setUserName(location_.user);
    db.setConnectOptions(location_.connect_options);  // no password: libpq reads PGPASSWORD or ~/.pgpass
  }
  if (!db.open()) {
    const QString why = db.lastError().text();
    fail(why.contains("password", Qt::CaseInsensitive)
             ? QString("cannot connect: %1 (the password comes from PGPASSWORD or ~/.pgpass)").arg(why)
             : QString("cannot open: %1").arg(why));
  }
}

QSqlQuery LearningDatabase::run(const QString& sql, const QList<QVariant>& binds) const {
  QSqlQuery query(QSqlDatabase::database(connection_, false));
  query.setForwardOnly(true);
  const auto check = [&](bool ok) {
    if (ok) return;
    const QSqlError e = query.lastError();  // the server's own text ("file is not a database") when there is one
    fail(QString("%1 (in: %2)").arg(e.databaseText().isEmpty() ? e.text() : e.databaseText(), sql.left(60)));
  };
  if (binds.isEmpty()) {  // not prepared: PostgreSQL cannot prepare BEGIN, COMMIT or DDL
    check(query.exec(sql));
    return query;
  }
  check(query.prepare(sql));
  for (const QVariant& b : binds) query.addBindValue(b);
  check(query.exec());
  return query;
}

QVariant LearningDatabase::scalar(const QString& sql, const QList<QVariant>& binds) const {
  QSqlQuery query = run(sql, binds);
  if (!query.next()) fail(QString("no result (in: %1)").arg(sql));
  return query.value(0);
}

bool LearningDatabase::tableExists(const char* name) const {
  return scalar(sql_.tableExists(), {QString::fromLatin1(name)}).toLongLong() > 0;
}

template <typename Work>
auto LearningDatabase::inTransaction(const char* begin, Work work) const {
  run(begin);
  try {
    auto result = work();
    run("COMMIT");
    return result;
  } catch (...) {
    QSqlQuery(QSqlDatabase::database(connection_, false)).exec("ROLLBACK");
    throw;
  }
}

void LearningDatabase::configureSqlite() {
  // Reading the header first turns a corrupt or foreign file into "file is not a database".
  scalar("PRAGMA user_version");
  const QString journal = scalar("PRAGMA journal_mode = WAL").toString();
  if (journal.compare("wal", Qt::CaseInsensitive) != 0)
    fail(QString("cannot switch to WAL journal mode (got '%1')").arg(journal));
  run("PRAGMA synchronous = FULL");
  run("PRAGMA foreign_keys = ON");
}

// The schema version, after checking that the tables are ours: 0 for an empty database.
LearningDatabase::StoredSchema LearningDatabase::storedSchema() const {
  const bool has_schema_table = tableExists("learning_schema");
  int version = 0;
  if (has_schema_table) {
    QSqlQuery row = run("SELECT application, version FROM learning_schema");
    if (!row.next() || row.value(0).toString() != QLatin1String(kLearningApplication))
      fail("not a MillExpert learning database (foreign learning_schema table)");
    version = row.value(1).toInt();
  }
  if (sql_.isSqlite()) {
    // Version-1 files keep the version in the header only; a header ahead of the table is newer.
    version = std::max(version, scalar("PRAGMA user_version").toInt());
    if (version == 0 && scalar("SELECT COUNT(*) FROM sqlite_master").toLongLong() != 0)
      fail("not a MillExpert learning database (an SQLite file with other tables)");
    if (version > 0 && scalar("PRAGMA application_id").toInt() != kApplicationId)
      fail("not a MillExpert learning database (foreign application_id)");
  } else if (!has_schema_table && tableExists("learning_entry")) {
    fail("not a MillExpert learning database (a learning_entry table without learning_schema)");
  }
  if (version > latestLearningSchemaVersion())
    fail(QString("schema version %1 was written by a newer MillExpert (this build reads up to %2)")
             .arg(version)
             .arg(latestLearningSchemaVersion()));
  return {version, has_schema_table};
}

void LearningDatabase::createSchemaTable(int version) {
  run(QString::fromLatin1(kLearningSchemaTable));
  run("INSERT INTO learning_schema (singleton, application, version) VALUES (1, ?, ?)",
      {QString::fromLatin1(kLearningApplication), version});
}

// One migration per transaction, each re-reading the version under the write lock: concurrent first
// openings apply every migration exactly once.
void LearningDatabase::migrate(int target_version) {
  if (const StoredSchema now = storedSchema(); now.version >= target_version && now.has_table) return;  // no lock
  for (;;) {
    const bool done = inTransaction(sql_.beginWrite(), [&] {
      if (*sql_.lockForMigration() != '\0') run(sql_.lockForMigration());
      const auto [version, has_table] = storedSchema();
      if (!has_table) createSchemaTable(version);
      if (version >= target_version) return true;
      applyMigration(version + 1);
      return false;
    });
    if (done) return;
  }
}

void LearningDatabase::applyMigration(int version) {
  const LearningMigration& migration = learningMigrations().at(static_cast<std::size_t>(version - 1));
  for (const char* statement : migration.statements) run(sql_.expand(statement));
  run("UPDATE learning_schema SET version = ?", {migration.version});
  if (sql_.isSqlite()) {
    run(QString("PRAGMA application_id = %1").arg(kApplicationId));
    run(QString("PRAGMA user_version = %1").arg(migration.version));  // what older builds read
  }
}

int LearningDatabase::schemaVersion() const {
  return storedSchema().version;
}

QString LearningDatabase::journalMode() const {
  return sql_.isSqlite() ? scalar("PRAGMA journal_mode").toString() : QString();
}

qint64 LearningDatabase::count() const {
  return scalar("SELECT COUNT(*) FROM learning_entry").toLongLong();
}

qint64 LearningDatabase::insert(const LearningRecord& record) {
  return insertAll({record}).front();
}

std::vector<qint64> LearningDatabase::insertAll(const std::vector<LearningRecord>& records) {
  for (std::size_t i = 0; i < records.size(); ++i) {
    try {
      validateLearningRecord(records[i]);
    } catch (const std::invalid_argument& e) {
      fail(records.size() == 1 ? QString("invalid record: %1").arg(e.what())
                               : QString("invalid record %1: %2").arg(i).arg(e.what()));
    }
  }
  return inTransaction(sql_.beginWrite(), [&] {
    std::vector<qint64> ids;
    ids.reserve(records.size());
    for (const LearningRecord& r : records) ids.push_back(insertInTransaction(r));
    return ids;
  });
}

qint64 LearningDatabase::insertInTransaction(const LearningRecord& input) {
  LearningRecord r = input;
  if (!r.time.isValid()) r.time = QDateTime::currentDateTimeUtc();
  if (r.uid.isEmpty()) r.uid = QUuid::createUuid().toString(QUuid::WithoutBraces);
  const QString timeText = learningTimeText(r.time);
  const QString objectivesJson = objectivesText(r.objectives);
  const QJsonValue mrr = r.objectives.value("mrr_cm3_s");
  const QVariant mrrValue = mrr.isDouble() ? QVariant(mrr.toDouble()) : QVariant(QMetaType(QMetaType::Double));
  std::optional<qint64> id;
  {
    QSqlQuery entry =
        run("INSERT INTO learning_entry (record_uid, time_utc, source, tool_id, tool_diameter_mm, tool_teeth, material,"
            " machine, spindle_power_w, max_spindle_rpm, speed_rpm, depth_mm, feed_mm_per_tooth, mrr_cm3_s,"
            " objectives_json, weight_count, checksum) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"
            " ON CONFLICT (record_uid) DO NOTHING RETURNING id",
            {r.uid, timeText, learningSourceName(r.source), r.tool.id, r.tool.diameter_mm, r.tool.teeth, r.material,
             nullableText(r.machine.name), r.machine.spindle_power_W, nullableDouble(r.machine.max_spindle_rpm),
             r.q.speed_rpm, r.q.depth_mm, r.q.feed_mm_per_tooth, mrrValue, objectivesJson,
             static_cast<qlonglong>(r.weights.size()), checksumOf(r, timeText, objectivesJson)});
    if (entry.next()) id = entry.value(0).toLongLong();
    entry.finish();
  }
  if (!id) return scalar("SELECT id FROM learning_entry WHERE record_uid = ?", {r.uid}).toLongLong();  // stored before
  for (std::size_t i = 0; i < r.weights.size(); ++i)
    run("INSERT INTO learning_weight (entry_id, position, value) VALUES (?, ?, ?)",
        {*id, static_cast<qlonglong>(i), r.weights[i]});
  return *id;
}

// The entries that match, newest first, each with its weights: one query over a snapshot, so that an
// entry is never seen without the weights its transaction wrote.
std::vector<LearningRecord> LearningDatabase::select(const QString& where, const QList<QVariant>& binds, int limit,
                                                     QStringList* problems) const {
  const QString sql =
      QString(
          "SELECT %1, w.position, w.value FROM (SELECT %2 FROM learning_entry%3"
          " ORDER BY time_utc DESC, id DESC%4) e LEFT JOIN learning_weight w ON w.entry_id = e.id"
          " ORDER BY e.time_utc DESC, e.id DESC, w.position")
          .arg(columns("e."), columns(""), where.isEmpty() ? QString() : " WHERE " + where, sql_.limit(limit));
  const std::vector<StoredEntry> entries = inTransaction(sql_.beginRead(), [&] {
    std::vector<StoredEntry> out;
    QSqlQuery rows = run(sql, binds);
    while (rows.next()) {
      const qint64 id = rows.value(kId).toLongLong();
      if (out.empty() || out.back().record.id != id) {
        try {
          out.push_back(entryOf(rows));
        } catch (const std::invalid_argument& e) {
          fail(QString("entry %1: %2").arg(id).arg(e.what()));
        }
      }
      if (!rows.value(kWeightPosition).isNull())
        out.back().record.weights.push_back(rows.value(kWeightValue).toDouble());
    }
    return out;
  });
  std::vector<LearningRecord> records;
  records.reserve(entries.size());
  for (const StoredEntry& e : entries) {
    if (problems != nullptr) checkEntry(e, problems);
    records.push_back(e.record);
  }
  return records;
}

std::vector<LearningRecord> LearningDatabase::history(const LearningHistoryQuery& query) const {
  QStringList where;
  QList<QVariant> binds;
  const auto filter = [&](const char* column, const std::optional<QString>& value) {
    if (!value) return;
    where << QString("%1 = ?").arg(QLatin1String(column));
    binds << *value;
  };
  filter("tool_id", query.tool);
  filter("material", query.material);
  filter("machine", query.machine);
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

QStringList LearningDatabase::facetValues(LearningFacet facet) const {
  const char* column = facet == LearningFacet::Tool       ? "tool_id"
                       : facet == LearningFacet::Material ? "material"
                                                          : "machine";
  QStringList values;
  for (QSqlQuery q = run(QString("SELECT DISTINCT %1 FROM learning_entry WHERE %1 IS NOT NULL").arg(column)); q.next();)
    values << q.value(0).toString();
  return values;
}

LearningConsistency LearningDatabase::checkConsistency() const {
  LearningConsistency c;
  if (sql_.isSqlite()) {
    QStringList integrity;
    for (QSqlQuery q = run("PRAGMA integrity_check"); q.next();) integrity << q.value(0).toString();
    c.integrity = integrity.join("; ");
    for (QSqlQuery q = run("PRAGMA foreign_key_check"); q.next();)
      c.problems << QString("foreign key: %1 row %2").arg(q.value(0).toString(), q.value(1).toString());
  } else {
    c.integrity = QStringLiteral("ok");  // the server enforces the foreign keys and owns its storage
  }
  c.entries = static_cast<qint64>(select({}, {}, 0, &c.problems).size());
  return c;
}

}  // namespace mx::app
