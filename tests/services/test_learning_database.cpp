// Rule 14 learning database (app/services/learning_database.h): schema creation, a record's round trip, the history /
// MRR-range / weight-suggestion queries, validation (bad source, weights off the simplex), error
// messages naming the file, several connections and threads. Writers killed mid-insert:
// services.learning_crash_safety.
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
#include "support/error_message.h"
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
  r.machine = {2745.3, 12000.0};
  r.q = {5800.0, 0.4924, 0.2722};
  r.objectives = QJsonObject{{"tol", 41.5}, {"mrr_cm3_s", mrr}, {"surf", 1.25}, {"ros", 0.8}, {"eta", 0.7}};
  r.source = LearningSource::Operator;
  return r;
}

const std::vector<double> kW{0.25, 0.25, 0.25, 0.25};

// The LearningDatabaseError message of fn(), or a null string when nothing is thrown.
template <typename F>
QString errorOf(F fn) {
  return mx::test::messageOf<LearningDatabaseError>(fn);
}

// A plain Qt Sql connection, to look at (or tamper with) the file behind the class's back.
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
  QTemporaryDir dir_;
  QString file(const char* name) const { return dir_.filePath(QString::fromLatin1(name)); }

 private slots:
  void schemaIsCreated() {
    const QString path = file("schema.sqlite");
    {
      LearningDatabase db(path);
      QCOMPARE(db.schemaVersion(), LearningDatabase::kSchemaVersion);
      QCOMPARE(db.journalMode(), QString("wal"));
      QCOMPARE(db.count(), 0);
      QVERIFY(db.checkConsistency().ok());
    }
    QVERIFY(QFile::exists(path));
    RawDb raw(path);
    QCOMPARE(raw.scalar("PRAGMA user_version").toInt(), 1);
    QCOMPARE(raw.scalar("PRAGMA application_id").toInt(), LearningDatabase::kApplicationId);
    QCOMPARE(
        raw.scalar("SELECT COUNT(*) FROM sqlite_master WHERE type = 'index' AND name LIKE 'learning_entry_%'").toInt(),
        4);
    LearningDatabase reopened(path, LearningDatabase::OpenMode::ExistingOnly);  // no re-creation
    QCOMPARE(reopened.schemaVersion(), 1);
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
    LearningDatabase db(file("roundtrip.sqlite"));
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
    QVERIFY(db.checkConsistency().ok());

    LearningRecord now = in;
    now.time = QDateTime();  // stamped at insertion
    db.insert(now);
    QVERIFY(std::abs(db.history().front().time.secsTo(QDateTime::currentDateTimeUtc())) < 60);
  }

  void historyPerToolAndMaterial() {
    LearningDatabase db(file("history.sqlite"));
    db.insert(sample("R1", "Aluminium", 30, 3, kW, 1.0, 1));
    db.insert(sample("R2", "Aluminium", 12.7, 2, kW, 1.0, 2));
    db.insert(sample("R1", "Steel", 30, 3, kW, 1.0, 3));
    db.insert(sample("R1", "Aluminium", 30, 3, kW, 1.0, 4));
    const auto r1 = db.history({QString("R1"), std::nullopt, 100});
    QCOMPARE(r1.size(), std::size_t{3});
    QCOMPARE(r1[0].time.time().minute(), 4);  // newest first
    QCOMPARE(r1[1].time.time().minute(), 3);
    QCOMPARE(r1[2].time.time().minute(), 1);
    const auto r1Al = db.history({QString("R1"), QString("Aluminium"), 100});
    QCOMPARE(r1Al.size(), std::size_t{2});
    QCOMPARE(db.history({std::nullopt, QString("Aluminium"), 100}).size(), std::size_t{3});
    QCOMPARE(db.history({std::nullopt, std::nullopt, 2}).size(), std::size_t{2});
    QCOMPARE(db.history({QString("nope"), std::nullopt, 100}).size(), std::size_t{0});
  }

  void weightsByMrrRange() {
    LearningDatabase db(file("mrr.sqlite"));
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
    QVERIFY(errorOf([&] { db.withMrrIn(2.0, 1.0); }).contains("is empty"));
  }

  void suggestionFromSimilarJobs() {
    LearningDatabase db(file("suggest.sqlite"));
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
    const QString path = file("bad.sqlite");
    LearningDatabase db(path);
    const QString sumError = errorOf([&] { db.insert(sample("R1", "Al", 10, 2, {0.5, 0.6}, 1)); });
    QVERIFY2(sumError.contains(path) && sumError.contains("must sum to 1"), qPrintable(sumError));
    QVERIFY(errorOf([&] { db.insert(sample("", "Al", 10, 2, kW, 1)); }).contains("tool.id"));
    LearningRecord text = sample("R1", "Al", 10, 2, kW, 1);
    text.objectives["tol"] = "long";
    QVERIFY(errorOf([&] { db.insert(text); }).contains("objectives.tol"));
    QCOMPARE(db.count(), 0);
    // The schema itself refuses a source outside the four (a foreign writer cannot sneak one in).
    RawDb raw(path);
    QVERIFY(
        !raw.exec("INSERT INTO learning_entry (time_utc, source, tool_id, tool_diameter_mm, tool_teeth, material,"
                  " spindle_power_w, speed_rpm, depth_mm, feed_mm_per_tooth, objectives_json, weight_count,"
                  " checksum) VALUES ('2024', 'robot', 'R1', 10, 2, 'Al', 1, 1, 1, 1, '{}', 1, 'x')"));
    QCOMPARE(db.count(), 0);
  }

  void errorsNameTheFile() {
    const QString missing = file("missing.sqlite");
    const QString e1 = errorOf([&] { LearningDatabase db(missing, LearningDatabase::OpenMode::ExistingOnly); });
    QVERIFY2(e1.contains(missing) && e1.contains("no such file"), qPrintable(e1));
    QVERIFY(!QFile::exists(missing));

    const QString unopenable = file("no/such/folder/x.sqlite");
    const QString e2 = errorOf([&] { LearningDatabase db(unopenable); });
    QVERIFY2(e2.contains(unopenable) && e2.contains("cannot open"), qPrintable(e2));

    const QString corrupt = file("corrupt.sqlite");
    QFile f(corrupt);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QByteArray(8192, 'x'));
    f.close();
    const QString e3 = errorOf([&] { LearningDatabase db(corrupt); });
    QVERIFY2(e3.contains(corrupt) && e3.contains("not a database"), qPrintable(e3));

    const QString foreign = file("foreign.sqlite");
    { RawDb(foreign).exec("CREATE TABLE t (x)"); }
    const QString e4 = errorOf([&] { LearningDatabase db(foreign); });
    QVERIFY2(e4.contains(foreign) && e4.contains("not a MillExpert learning database"), qPrintable(e4));

    const QString newer = file("newer.sqlite");
    { LearningDatabase db(newer); }
    { RawDb(newer).exec("PRAGMA user_version = 99"); }
    const QString e5 = errorOf([&] { LearningDatabase db(newer); });
    QVERIFY2(e5.contains(newer) && e5.contains("newer"), qPrintable(e5));
    QVERIFY(QSqlDatabase::connectionNames().isEmpty());  // failed openings leave no connection behind
  }

  void twoConnectionsAndThreads() {
    const QString path = file("shared.sqlite");
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
};

MX_REGISTER_TEST(TestLearningDatabase)
#include "test_learning_database.moc"
