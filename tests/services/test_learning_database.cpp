// Rule 14 learning database (app/services/learning_database.h), every test against both back ends: an
// SQLite file and a real PostgreSQL server (support/learning_backends.h). Schema creation, a record's
// round trip, the history / machine / MRR-range / weight-suggestion queries, validation (bad source,
// weights off the simplex), a record stored once per uid, error messages naming the file or URL,
// several connections and threads. Concurrent writers and writers killed mid-transaction:
// services.learning_concurrency, services.learning_crash_safety; older schemas:
// services.learning_migrations.
#include <QDir>
#include <QFile>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <atomic>
#include <cmath>
#include <thread>

#include "services/learning_database.h"
#include "services/learning_migrations.h"
#include "support/error_message.h"
#include "support/learning_backends.h"
#include "test_registry.h"

using mx::app::JobFeatures;
using mx::app::LearningDatabase;
using mx::app::LearningDatabaseError;
using mx::app::LearningRecord;
using mx::app::LearningSource;

namespace {

LearningRecord sample(const QString& tool, const QString& material, double diameter, int teeth,
                      std::vector<double> weights, double mrr, int minute = 0) {
  LearningRecord r;
  r.time = QDateTime(QDate(2024, 5, 1), QTime(8, minute, 0, 125), Qt::UTC);
  r.weights = std::move(weights);
  r.tool = {tool, diameter, teeth};
  r.material = material;
  r.machine = {QString("DMU-50"), 2745.3, 12000.0};
  r.q = {5800.0, 0.4924, 0.2722};
  r.objectives = QJsonObject{{"tol", 41.5}, {"mrr_cm3_s", mrr}, {"surf", 1.25}, {"ros", 0.8}, {"eta", 0.7}};
  r.source = LearningSource::Operator;
  return r;
}

const std::vector<double> kW{0.25, 0.25, 0.25, 0.25};

// The LearningDatabaseError message of fn(), or a null string when nothing is thrown.
template <typename F>
QString learningErrorOf(F fn) {
  return mx::test::messageOf<LearningDatabaseError>(fn);
}

bool rawExec(const LearningDatabase& db, const QString& sql) {
  return QSqlQuery(QSqlDatabase::database(db.connectionName(), false)).exec(sql);
}

// A plain Qt Sql connection to an SQLite file, to look at (or tamper with) it behind the class's back.
struct RawDb {
  explicit RawDb(const QString& path) : name(QString("raw_%1").arg(++counter)) {
    QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", name);
    db.setDatabaseName(path);
    db.open();
  }
  ~RawDb() {
    { QSqlDatabase::database(name, false).close(); }
    QSqlDatabase::removeDatabase(name);
  }
  QVariant scalar(const QString& sql) {
    QSqlQuery q(QSqlDatabase::database(name, false));
    if (!q.exec(sql) || !q.next()) return {};
    return q.value(0);
  }
  bool exec(const QString& sql) { return QSqlQuery(QSqlDatabase::database(name, false)).exec(sql); }
  QString name;
  static inline int counter = 0;
};

}  // namespace

class TestLearningDatabase : public QObject {
  Q_OBJECT
  mx::test::LearningBackends backends_;
  QString file(const char* name) const { return backends_.folder().filePath(QString::fromLatin1(name)); }

 private slots:
  void initTestCase_data() { mx::test::LearningBackends::addRows(); }

  void schemaIsCreated() {
    MX_NEW_DATABASE(location, "schema");
    const int latest = mx::app::latestLearningSchemaVersion();
    QCOMPARE(latest, 2);
    {
      LearningDatabase db(location);
      QCOMPARE(db.schemaVersion(), latest);
      QCOMPARE(db.journalMode(), backends_.postgres() ? QString() : QString("wal"));
      QCOMPARE(db.count(), 0);
      QVERIFY(db.checkConsistency().ok());
      QCOMPARE(mx::test::rawScalar(db, "SELECT version FROM learning_schema").toInt(), latest);
      QCOMPARE(mx::test::rawScalar(db, "SELECT application FROM learning_schema").toString(),
               QString(mx::app::kLearningApplication));
      const QString indexes =
          backends_.postgres()
              ? "SELECT COUNT(*) FROM pg_indexes WHERE indexname LIKE 'learning_entry_%'"
                " AND indexname <> 'learning_entry_pkey'"
              : "SELECT COUNT(*) FROM sqlite_master WHERE type = 'index' AND name LIKE 'learning_entry_%'";
      QCOMPARE(mx::test::rawScalar(db, indexes).toInt(), 6);  // tool, material, mrr, time, uid, machine
    }
    if (!backends_.postgres()) {
      QVERIFY(QFile::exists(location));
      RawDb raw(location);
      QCOMPARE(raw.scalar("PRAGMA user_version").toInt(), latest);  // what older builds read
      QCOMPARE(raw.scalar("PRAGMA application_id").toInt(), LearningDatabase::kApplicationId);
    }
    LearningDatabase reopened(location, LearningDatabase::OpenMode::ExistingOnly);  // no re-creation
    QCOMPARE(reopened.schemaVersion(), latest);
  }

  void defaultPathIsTheApplicationsDataFolder() {
    const QString appName = QCoreApplication::applicationName();
    const bool test_mode = QStandardPaths::isTestModeEnabled();
    QStandardPaths::setTestModeEnabled(true);
    const QString path = LearningDatabase::defaultPath();
    QStandardPaths::setTestModeEnabled(test_mode);
    QVERIFY2(path.endsWith("MillExpert/MillExpert/learning.sqlite"), qPrintable(path));
    QVERIFY2(path.startsWith(QDir::homePath() + "/"), qPrintable(path));  // the runner's private HOME
    QCOMPARE(QCoreApplication::applicationName(), appName);               // restored
  }

  void recordRoundTrip() {
    MX_NEW_DATABASE(location, "roundtrip");
    LearningDatabase db(location);
    LearningRecord in = sample("R1", "Ti6Al4V", 30.0, 3, {0.1, 0.6, 0.2, 0.1}, 2.5);
    in.machine.max_spindle_rpm.reset();
    in.source = LearningSource::Feedback;
    in.objectives["power_W"] = QJsonValue();  // null terms survive
    const qint64 id = db.insert(in);
    QVERIFY(id > 0);
    const std::vector<LearningRecord> out = db.history();
    QCOMPARE(out.size(), std::size_t{1});
    const LearningRecord& r = out.front();
    QCOMPARE(r.id, id);
    QCOMPARE(r.time, in.time);
    QCOMPARE(r.weights, in.weights);
    QCOMPARE(r.tool.id, QString("R1"));
    QCOMPARE(r.tool.diameter_mm, 30.0);
    QCOMPARE(r.tool.teeth, 3);
    QCOMPARE(r.material, QString("Ti6Al4V"));
    QCOMPARE(r.machine.name, std::optional<QString>("DMU-50"));
    QCOMPARE(r.machine.spindle_power_W, 2745.3);
    QVERIFY(!r.machine.max_spindle_rpm);
    QCOMPARE(r.q.speed_rpm, 5800.0);
    QCOMPARE(r.q.depth_mm, 0.4924);
    QCOMPARE(r.q.feed_mm_per_tooth, 0.2722);
    QCOMPARE(r.objectives, in.objectives);
    QCOMPARE(r.source, LearningSource::Feedback);
    const QJsonObject entry = mx::app::learningEntryJson(r);
    QCOMPARE(entry["time"].toString(), QString("2024-05-01T08:00:00.125Z"));
    QCOMPARE(entry["source"].toString(), QString("feedback"));
    QCOMPARE(entry["machine"].toString(), QString("DMU-50"));
    QCOMPARE(r.uid.size(), 36);  // a UUID chosen at insertion
    QVERIFY(db.checkConsistency().ok());

    LearningRecord now = in;
    now.time = QDateTime();  // stamped at insertion
    now.machine.name.reset();
    db.insert(now);
    const LearningRecord newest = db.history().front();
    QVERIFY(std::abs(newest.time.secsTo(QDateTime::currentDateTimeUtc())) < 60);
    QVERIFY(!newest.machine.name);
    QVERIFY(mx::app::learningEntryJson(newest)["machine"].isNull());
    QVERIFY(newest.uid != r.uid);
    QVERIFY(db.checkConsistency().ok());
  }

  // Doubles keep all 17 digits through either back end: the checksum covers them.
  void doublesRoundTripExactly() {
    MX_NEW_DATABASE(location, "doubles");
    LearningDatabase db(location);
    LearningRecord in = sample("R1", "Al", 0.1 + 0.2, 3, {1.0 / 3.0, 2.0 / 3.0}, 1e-300, 1);
    in.q = {5800.000000000001, 4.9406564584124654e-324 * 1e300, 0.27220000000000005};
    in.objectives["tol"] = 1.7976931348623157e308;
    db.insert(in);
    const LearningRecord out = db.history().front();
    QCOMPARE(out.tool.diameter_mm, 0.1 + 0.2);
    QCOMPARE(out.weights, in.weights);
    QCOMPARE(out.q.speed_rpm, in.q.speed_rpm);
    QCOMPARE(out.q.depth_mm, in.q.depth_mm);
    QCOMPARE(out.q.feed_mm_per_tooth, in.q.feed_mm_per_tooth);
    QCOMPARE(out.objectives, in.objectives);
    QVERIFY(db.checkConsistency().ok());
  }

  // A record's uid is unique: a retried insert (or a re-import) stores it once and returns its id.
  void aRecordIsStoredOncePerUid() {
    MX_NEW_DATABASE(location, "uid");
    LearningDatabase db(location);
    LearningRecord r = sample("R1", "Al", 10, 2, kW, 1.0, 1);
    r.uid = "3f1c7e0a-0000-4000-8000-000000000001";
    const qint64 first = db.insert(r);
    QCOMPARE(db.insert(r), first);
    const std::vector<qint64> ids = db.insertAll({r, sample("R2", "Al", 10, 2, kW, 1.0, 2)});
    QCOMPARE(ids.size(), std::size_t{2});
    QCOMPARE(ids[0], first);
    QVERIFY(ids[1] != first);
    QCOMPARE(db.count(), 2);
    QCOMPARE(mx::test::rawScalar(db, "SELECT COUNT(*) FROM learning_weight").toInt(), 8);  // no weights written twice
    QVERIFY(db.checkConsistency().ok());
  }

  // insertAll validates every record before it writes any: a bad one stores none of them.
  void insertAllIsAllOrNothing() {
    MX_NEW_DATABASE(location, "batch");
    LearningDatabase db(location);
    std::vector<LearningRecord> records;
    records.reserve(5);
    for (int i = 0; i < 5; ++i) records.push_back(sample(QString("R%1").arg(i), "Al", 10, 2, kW, 1.0, i));
    records[3].weights = {0.5, 0.6};
    const QString e = learningErrorOf([&] { db.insertAll(records); });
    QVERIFY2(e.contains("invalid record 3") && e.contains("must sum to 1"), qPrintable(e));
    QCOMPARE(db.count(), 0);
    records[3].weights = kW;
    QCOMPARE(db.insertAll(records).size(), std::size_t{5});
    QCOMPARE(db.count(), 5);
  }

  void historyPerToolMaterialAndMachine() {
    MX_NEW_DATABASE(location, "history");
    LearningDatabase db(location);
    db.insert(sample("R1", "Aluminium", 30, 3, kW, 1.0, 1));
    db.insert(sample("R2", "Aluminium", 12.7, 2, kW, 1.0, 2));
    db.insert(sample("R1", "Steel", 30, 3, kW, 1.0, 3));
    db.insert(sample("R1", "Aluminium", 30, 3, kW, 1.0, 4));
    const auto r1 = db.history({QString("R1"), std::nullopt, std::nullopt, 100});
    QCOMPARE(r1.size(), std::size_t{3});
    QCOMPARE(r1[0].time.time().minute(), 4);  // newest first
    QCOMPARE(r1[1].time.time().minute(), 3);
    QCOMPARE(r1[2].time.time().minute(), 1);
    const auto r1Al = db.history({QString("R1"), QString("Aluminium"), std::nullopt, 100});
    QCOMPARE(r1Al.size(), std::size_t{2});
    QCOMPARE(db.history({std::nullopt, QString("Aluminium"), std::nullopt, 100}).size(), std::size_t{3});
    QCOMPARE(db.history({std::nullopt, std::nullopt, std::nullopt, 2}).size(), std::size_t{2});
    QCOMPARE(db.history({QString("nope"), std::nullopt, std::nullopt, 100}).size(), std::size_t{0});
    LearningRecord other = sample("R1", "Aluminium", 30, 3, kW, 1.0, 5);
    other.machine.name = "HERMLE-C42";
    db.insert(other);
    const auto hermle = db.history({std::nullopt, std::nullopt, QString("HERMLE-C42"), 100});
    QCOMPARE(hermle.size(), std::size_t{1});
    QCOMPARE(hermle.front().time.time().minute(), 5);
    QCOMPARE(db.history({std::nullopt, QString("Aluminium"), QString("DMU-50"), 100}).size(), std::size_t{3});
    QCOMPARE(db.history({std::nullopt, std::nullopt, std::nullopt, 0}).size(), std::size_t{5});  // no limit
    LearningRecord unnamed = sample("R3", "Brass", 30, 3, kW, 1.0, 6);
    unnamed.machine.name.reset();
    db.insert(unnamed);
    const auto sorted = [](QStringList l) { return l.sort(), l; };
    QCOMPARE(sorted(db.facetValues(mx::app::LearningFacet::Tool)), (QStringList{"R1", "R2", "R3"}));
    QCOMPARE(sorted(db.facetValues(mx::app::LearningFacet::Material)), (QStringList{"Aluminium", "Brass", "Steel"}));
    QCOMPARE(sorted(db.facetValues(mx::app::LearningFacet::Machine)), (QStringList{"DMU-50", "HERMLE-C42"}));
  }

  void weightsByMrrRange() {
    MX_NEW_DATABASE(location, "mrr");
    LearningDatabase db(location);
    db.insert(sample("R1", "Aluminium", 30, 3, {0.7, 0.1, 0.1, 0.1}, 1.0, 1));
    db.insert(sample("R1", "Aluminium", 30, 3, {0.1, 0.7, 0.1, 0.1}, 2.0, 2));
    db.insert(sample("R1", "Aluminium", 30, 3, {0.1, 0.1, 0.7, 0.1}, 3.0, 3));
    LearningRecord noMrr = sample("R1", "Aluminium", 30, 3, kW, 0.0, 4);
    noMrr.objectives.remove("mrr_cm3_s");
    db.insert(noMrr);
    const auto hits = db.withMrrIn(1.5, 3.0);
    QCOMPARE(hits.size(), std::size_t{2});
    QCOMPARE(hits[0].weights, (std::vector<double>{0.1, 0.1, 0.7, 0.1}));
    QCOMPARE(hits[1].weights, (std::vector<double>{0.1, 0.7, 0.1, 0.1}));
    QCOMPARE(db.withMrrIn(0.0, 10.0).size(), std::size_t{3});  // the row without MRR never matches
    QCOMPARE(db.withMrrIn(3.5, 9.0).size(), std::size_t{0});
    QVERIFY(learningErrorOf([&] { db.withMrrIn(2.0, 1.0); }).contains("is empty"));
  }

  void suggestionFromSimilarJobs() {
    MX_NEW_DATABASE(location, "suggest");
    LearningDatabase db(location);
    QVERIFY(!db.suggestInitialWeights({"Aluminium", 10.0, 2, 4}));  // empty database
    const qint64 near = db.insert(sample("A", "Aluminium", 10.0, 2, {0.4, 0.4, 0.2, 0.0}, 1, 1));
    const qint64 second = db.insert(sample("B", "Aluminium", 12.0, 2, {0.2, 0.2, 0.2, 0.4}, 1, 2));
    db.insert(sample("C", "Aluminium", 30.0, 4, {1.0, 0.0, 0.0, 0.0}, 1, 3));  // far
    db.insert(sample("D", "Steel", 10.0, 2, {0.0, 0.0, 0.0, 1.0}, 1, 4));      // other material
    db.insert(sample("E", "Aluminium", 10.0, 2, {0.5, 0.3, 0.2}, 1, 5));       // 3 weights
    const auto s = db.suggestInitialWeights({"Aluminium", 10.0, 2, 4}, 2);
    QVERIFY(s);
    QCOMPARE(s->from_ids, (std::vector<qint64>{near, second}));
    QCOMPARE(s->distances[0], 0.0);
    QCOMPARE(s->distances[1], 0.2);
    const std::vector<double> expected{0.3, 0.3, 0.2, 0.2};
    double sum = 0.0;
    for (std::size_t i = 0; i < 4; ++i) {
      QVERIFY(std::abs(s->weights[i] - expected[i]) < 1e-12);
      sum += s->weights[i];
    }
    QVERIFY(std::abs(sum - 1.0) < 1e-12);
    QCOMPARE(db.suggestInitialWeights({"Aluminium", 10.0, 2, 3}, 3)->weights.size(), std::size_t{3});
    QVERIFY(!db.suggestInitialWeights({"Inconel", 10.0, 2, 4}));
    // Renormalisation onto the simplex.
    QCOMPARE(mx::app::projectOntoSimplex({2.0, -1.0, 2.0}), (std::vector<double>{0.5, 0.0, 0.5}));
    QCOMPARE(mx::app::projectOntoSimplex({0.0, 0.0}), (std::vector<double>{0.5, 0.5}));
  }

  void badSourceAndRecordRejected() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, mx::app::parseLearningSource("robot"));
    QCOMPARE(mx::app::parseLearningSource("rule"), LearningSource::Rule);
    MX_NEW_DATABASE(path, "bad");
    LearningDatabase db(path);
    const QString sumError = learningErrorOf([&] { db.insert(sample("R1", "Al", 10, 2, {0.5, 0.6}, 1)); });
    QVERIFY2(sumError.contains(path) && sumError.contains("must sum to 1"), qPrintable(sumError));
    QVERIFY(learningErrorOf([&] { db.insert(sample("", "Al", 10, 2, kW, 1)); }).contains("tool.id"));
    LearningRecord text = sample("R1", "Al", 10, 2, kW, 1);
    text.objectives["tol"] = "long";
    QVERIFY(learningErrorOf([&] { db.insert(text); }).contains("objectives.tol"));
    QCOMPARE(db.count(), 0);
    // The schema itself refuses a source outside the four (a foreign writer cannot sneak one in).
    QVERIFY(!rawExec(db,
                     "INSERT INTO learning_entry (time_utc, source, tool_id, tool_diameter_mm, tool_teeth, material,"
                     " spindle_power_w, speed_rpm, depth_mm, feed_mm_per_tooth, objectives_json, weight_count,"
                     " checksum) VALUES ('2024', 'robot', 'R1', 10, 2, 'Al', 1, 1, 1, 1, '{}', 1, 'x')"));
    QCOMPARE(db.count(), 0);
  }

  void errorsNameTheFile() {
    if (backends_.postgres()) {
      errorsNameTheServer();
      return;
    }
    const QString missing = file("missing.sqlite");
    const QString e1 = learningErrorOf([&] { LearningDatabase db(missing, LearningDatabase::OpenMode::ExistingOnly); });
    QVERIFY2(e1.contains(missing) && e1.contains("no such file"), qPrintable(e1));
    QVERIFY(!QFile::exists(missing));

    const QString unopenable = file("no/such/folder/x.sqlite");
    const QString e2 = learningErrorOf([&] { LearningDatabase db(unopenable); });
    QVERIFY2(e2.contains(unopenable) && e2.contains("cannot open"), qPrintable(e2));

    const QString corrupt = file("corrupt.sqlite");
    QFile f(corrupt);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QByteArray(8192, 'x'));
    f.close();
    const QString e3 = learningErrorOf([&] { LearningDatabase db(corrupt); });
    QVERIFY2(e3.contains(corrupt) && e3.contains("not a database"), qPrintable(e3));

    const QString foreign = file("foreign.sqlite");
    { RawDb(foreign).exec("CREATE TABLE t (x)"); }
    const QString e4 = learningErrorOf([&] { LearningDatabase db(foreign); });
    QVERIFY2(e4.contains(foreign) && e4.contains("not a MillExpert learning database"), qPrintable(e4));

    const QString newer = file("newer.sqlite");
    { LearningDatabase db(newer); }
    { RawDb(newer).exec("UPDATE learning_schema SET version = 99"); }
    const QString e5 = learningErrorOf([&] { LearningDatabase db(newer); });
    QVERIFY2(e5.contains(newer) && e5.contains("schema version 99") && e5.contains("newer"), qPrintable(e5));
    const QString header_newer = file("header-newer.sqlite");  // what a newer build of the old layout writes
    { LearningDatabase db(header_newer); }
    { RawDb(header_newer).exec("PRAGMA user_version = 7"); }
    QVERIFY(learningErrorOf([&] { LearningDatabase db(header_newer); }).contains("schema version 7"));
    QVERIFY(QSqlDatabase::connectionNames().isEmpty());  // failed openings leave no connection behind
  }

  void twoConnectionsAndThreads() {
    MX_NEW_DATABASE(path, "shared");
    LearningDatabase a(path);
    LearningDatabase b(path);
    QVERIFY(a.connectionName() != b.connectionName());
    a.insert(sample("R1", "Aluminium", 30, 3, kW, 1.0));
    QCOMPARE(b.count(), 1);  // committed writes are visible to the other connection
    b.insert(sample("R2", "Aluminium", 12.7, 2, kW, 1.0));
    QCOMPARE(a.count(), 2);

    constexpr int kPerThread = 20;
    std::vector<std::thread> writers;
    writers.reserve(3);
    std::atomic<int> failures{0};
    for (int t = 0; t < 3; ++t)
      writers.emplace_back([&, t] {
        try {
          LearningDatabase own(path);  // one instance per thread
          for (int i = 0; i < kPerThread; ++i) own.insert(sample(QString("T%1").arg(t), "Aluminium", 10, 2, kW, 1.0));
        } catch (const std::exception& e) {
          qWarning("%s", e.what());
          ++failures;
        }
      });
    for (int i = 0; i < kPerThread; ++i) a.insert(sample("main", "Aluminium", 10, 2, kW, 1.0));
    for (std::thread& w : writers) w.join();
    QCOMPARE(failures.load(), 0);
    QCOMPARE(b.count(), 2 + 4 * kPerThread);
    QVERIFY(b.checkConsistency().ok());
  }

 private:
  // The PostgreSQL errors name the URL (never a password) and say what is wrong.
  void errorsNameTheServer() {
    mx::test::PostgresServer* server = backends_.server();
    QVERIFY(server != nullptr);
    const QString missing = server->url("no_such_database");
    const QString e1 = learningErrorOf([&] { LearningDatabase db(missing); });
    QVERIFY2(e1.contains("'" + missing + "'") && e1.contains("cannot open") && e1.contains("does not exist"),
             qPrintable(e1));

    const QString closed = QString("postgresql://postgres@127.0.0.1:%1/postgres").arg(mx::test::freeLoopbackPort());
    const QString e2 = learningErrorOf([&] { LearningDatabase db(closed); });
    QVERIFY2(e2.contains(closed) && e2.contains("cannot open"), qPrintable(e2));

    const QString e3 = learningErrorOf([&] { LearningDatabase db("postgresql://shop:secret@127.0.0.1/learning"); });
    QVERIFY2(e3.contains("password is not accepted") && !e3.contains("secret"), qPrintable(e3));

    MX_NEW_DATABASE(foreign, "foreign");
    {
      LearningDatabase db(foreign);
      QVERIFY(rawExec(db, "DROP TABLE learning_schema"));
    }
    const QString e4 = learningErrorOf([&] { LearningDatabase db(foreign); });
    QVERIFY2(e4.contains(foreign) && e4.contains("not a MillExpert learning database"), qPrintable(e4));

    MX_NEW_DATABASE(newer, "newer");
    {
      LearningDatabase db(newer);
      QVERIFY(rawExec(db, "UPDATE learning_schema SET version = 99"));
    }
    const QString e5 = learningErrorOf([&] { LearningDatabase db(newer); });
    QVERIFY2(e5.contains(newer) && e5.contains("schema version 99") && e5.contains("newer"), qPrintable(e5));
    QVERIFY(QSqlDatabase::connectionNames().isEmpty());
  }
};

MX_REGISTER_TEST(TestLearningDatabase)
#include "test_learning_database.moc"
