// The learning database shared by many machines (app/services/learning_database.h), against both back
// ends (support/learning_backends.h): 8 writer processes (learning_writer, one machine each) × 500
// records at the same time lose nothing and duplicate nothing, while a reader in this process never
// sees half a record; a writer killed with SIGKILL in the middle of a transaction leaves no part of it,
// holds no lock afterwards, and the database takes new records.
#include <QElapsedTimer>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <csignal>
#include <memory>
#include <set>

#include "services/learning_database.h"
#include "support/kill_loop.h"
#include "support/learning_backends.h"
#include "test_registry.h"

using mx::app::LearningDatabase;

namespace {

constexpr int kWriters = 8;
constexpr int kRecordsPerWriter = 500;
constexpr int kBatchRecords = 20000;  // one transaction that lasts seconds: the kill lands inside it

bool allFinished(const std::vector<std::unique_ptr<QProcess>>& writers) {
  return std::all_of(writers.begin(), writers.end(), [](const auto& w) {
    return mx::test::hasEnded(w->processId()) || w->state() == QProcess::NotRunning;
  });
}

}  // namespace

class TestLearningConcurrency : public QObject {
  Q_OBJECT
  mx::test::LearningBackends backends_;

 private slots:
  void initTestCase_data() { mx::test::LearningBackends::addRows(); }

  void concurrentWritersLoseAndDuplicateNothing() {
    MX_NEW_DATABASE(location, "writers");
    LearningDatabase reader(location);  // creates the schema before the writers race
    std::vector<std::unique_ptr<QProcess>> writers;
    for (int w = 0; w < kWriters; ++w) {
      auto writer = std::make_unique<QProcess>();
      writer->start(MX_LEARNING_WRITER_PATH,
                    {location, QString::number(kRecordsPerWriter), "--machine", QString("M%1").arg(w)});
      QVERIFY2(writer->waitForStarted(10000), qPrintable(writer->errorString()));
      writers.push_back(std::move(writer));
    }
    // While they write: every snapshot the reader takes holds whole records only.
    QElapsedTimer clock;
    clock.start();
    int snapshots = 0;
    while (!allFinished(writers) && clock.elapsed() < 240000) {
      const mx::app::LearningConsistency c = reader.checkConsistency();
      QVERIFY2(c.ok(), qPrintable(c.integrity + " " + c.problems.join("; ")));
      ++snapshots;
    }
    for (const auto& writer : writers) {
      QVERIFY2(writer->waitForFinished(10000), "a writer did not finish within 240 s");
      QVERIFY2(writer->exitStatus() == QProcess::NormalExit && writer->exitCode() == 0,
               writer->readAllStandardError().constData());
    }
    qInfo("%d writers x %d records in %lld ms, %d consistent snapshots read meanwhile", kWriters, kRecordsPerWriter,
          static_cast<long long>(clock.elapsed()), snapshots);
    QVERIFY(snapshots >= 1);
    QCOMPARE(reader.count(), kWriters * kRecordsPerWriter);
    QCOMPARE(mx::test::rawScalar(reader, "SELECT COUNT(DISTINCT record_uid) FROM learning_entry").toInt(),
             kWriters * kRecordsPerWriter);
    QCOMPARE(mx::test::rawScalar(reader, "SELECT COUNT(*) FROM learning_weight").toInt(),
             4 * kWriters * kRecordsPerWriter);
    for (int w = 0; w < kWriters; ++w) {
      mx::app::LearningHistoryQuery query;
      query.machine = QString("M%1").arg(w);
      query.limit = 0;
      std::set<int> indexes;
      for (const mx::app::LearningRecord& r : reader.history(query))
        indexes.insert(r.objectives.value("writer_index").toInt());
      QCOMPARE(static_cast<int>(indexes.size()), kRecordsPerWriter);  // each of 0..499 exactly once
      QCOMPARE(*indexes.begin(), 0);
      QCOMPARE(*indexes.rbegin(), kRecordsPerWriter - 1);
    }
    QVERIFY(reader.checkConsistency().ok());
  }

  void writerKilledMidTransactionLeavesNoPartialRecord() {
    MX_NEW_DATABASE(location, "killed");
    LearningDatabase db(location);
    db.insert(recordBefore());
    QProcess writer;
    writer.start(MX_LEARNING_WRITER_PATH, {location, QString::number(kBatchRecords), "--machine", "K1", "--batch"});
    QByteArray seen;
    QVERIFY2(mx::test::waitForLine(writer, seen, "begin batch", 60000), writer.readAllStandardError().constData());
    // Inside the transaction: its first rows are written (visible to nobody else) when the kill comes.
    QThread::msleep(300);
    seen += writer.readAllStandardOutput();
    ::kill(static_cast<pid_t>(writer.processId()), SIGKILL);
    QVERIFY(writer.waitForFinished(10000));
    seen += writer.readAllStandardOutput();
    QVERIFY2(!seen.contains("end batch"), "the batch committed before the kill: make it longer");
    QCOMPARE(writer.exitStatus(), QProcess::CrashExit);

    // Nothing of it is stored, and nothing of it holds a lock: the server ended the dead session.
    QVERIFY(waitUntilNoOpenTransaction(db));
    QCOMPARE(db.count(), 1);
    QCOMPARE(mx::test::rawScalar(db, "SELECT COUNT(*) FROM learning_weight").toInt(), 4);
    QVERIFY(db.checkConsistency().ok());
    mx::app::LearningRecord after = recordBefore();
    after.uid.clear();
    db.insert(after);
    QCOMPARE(db.count(), 2);
  }

 private:
  static mx::app::LearningRecord recordBefore() {
    mx::app::LearningRecord r;
    r.weights = {0.25, 0.25, 0.25, 0.25};
    r.tool = {"R1", 10.0, 2};
    r.material = "Aluminium";
    r.machine = {QString("K0"), 5000.0, std::nullopt};
    r.q = {5000.0, 1.0, 0.1};
    r.objectives = QJsonObject{{"mrr_cm3_s", 1.0}};
    return r;
  }

  bool waitUntilNoOpenTransaction(const LearningDatabase& db) {
    if (!backends_.postgres()) return true;  // SQLite: the lock died with the process
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 10000) {
      if (mx::test::rawScalar(db,
                              "SELECT COUNT(*) FROM pg_stat_activity WHERE state LIKE 'idle in transaction%'"
                              " OR (state = 'active' AND pid <> pg_backend_pid() AND backend_type = 'client backend')")
              .toInt() == 0)
        return true;
      QThread::msleep(20);
    }
    return false;
  }
};

MX_REGISTER_TEST(TestLearningConcurrency)
#include "test_learning_concurrency.moc"
