// The learning database off the GUI thread (app/gui/learning_client.h): records and history queries
// run on the learning thread against an SQLite file and a real PostgreSQL server (support/
// postgres_server.h), filtered by machine; a newer history query makes the older answer stale; the
// connection test reports schema and count, a missing file without creating it, and an unreachable
// server; while a test waits for a server that never answers, the GUI event loop stays responsive and
// a newer test answers first, the older one never.
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QThread>
#include <QTimer>

#include "learning_client.h"
#include "services/learning_database.h"
#include "support/event_loop_probe.h"
#include "support/postgres_server.h"
#include "test_registry.h"

using mx::gui::LearningClient;
using mx::gui::LearningHistoryRequest;
using mx::gui::LearningHistoryResult;

namespace {

mx::app::LearningRecord record(const QString& tool, const std::optional<QString>& machine, double mrr) {
  mx::app::LearningRecord r;
  r.weights = {0.25, 0.25, 0.25, 0.25};
  r.tool = {tool, 30.0, 3};
  r.material = "Aluminium";
  r.machine = {machine, 2745.3, std::nullopt};
  r.q = {5800.0, 0.4924, 0.2722};
  r.objectives = QJsonObject{{"tol", 41.5}, {"mrr_cm3_s", mrr}, {"surf", 1.25}, {"ros", 0.8}};
  return r;
}

}  // namespace

class TestLearningClient : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  std::unique_ptr<mx::test::PostgresServer> server_;
  int databases_ = 0;

  // A new empty database: a file in the test's folder, or a database on the real server.
  QString newDatabase(bool postgres, const QString& name) {
    if (!postgres) return dir_.filePath(name + ".sqlite");
    if (!server_) {
      server_ = std::make_unique<mx::test::PostgresServer>();
      if (const QString why = server_->start(); !why.isEmpty()) {
        server_.reset();
        QTest::qFail(qPrintable("the PostgreSQL server did not start: " + why), __FILE__, __LINE__);
        return {};
      }
    }
    const QString database = QString("%1_%2").arg(name).arg(++databases_);
    QString why;
    if (!server_->createDatabase(database, &why)) {
      QTest::qFail(qPrintable("CREATE DATABASE " + database + ": " + why), __FILE__, __LINE__);
      return {};
    }
    return server_->url(database);
  }

 private slots:
  void recordsAndHistoryOnTheLearningThread_data() {
    QTest::addColumn<bool>("postgres");
    QTest::newRow("sqlite") << false;
    QTest::newRow("postgresql") << true;
  }
  void recordsAndHistoryOnTheLearningThread() {
    QFETCH(bool, postgres);
    const QString location = newDatabase(postgres, "history");
    if (location.isEmpty()) return;
    LearningClient client;
    QSignalSpy recorded(&client, &LearningClient::recorded);
    QSignalSpy loaded(&client, &LearningClient::historyLoaded);
    QSignalSpy failed(&client, &LearningClient::recordFailed);
    QVERIFY(client.idle());
    client.record(location, record("R1", QString("VMC-7"), 1.5));
    client.record(location, record("R2", QString("DMU 50"), 2.5));
    client.record(location, record("R1", std::nullopt, 3.5));
    QVERIFY(!client.idle());
    LearningHistoryRequest request;
    request.machine = "VMC-7";
    const quint64 generation = client.loadHistory(location, request);
    QVERIFY(QTest::qWaitFor([&] { return client.idle(); }, 30000));
    QCOMPARE(failed.count(), 0);
    QCOMPARE(recorded.count(), 3);
    QVERIFY(recorded.at(0).at(1).toLongLong() > 0);
    QCOMPARE(loaded.count(), 1);
    QCOMPARE(loaded.at(0).at(0).toULongLong(), generation);
    const auto result = loaded.at(0).at(1).value<LearningHistoryResult>();
    QCOMPARE(result.records.size(), std::size_t(1));
    QCOMPARE(result.records.front().tool.id, QString("R1"));
    QCOMPARE(result.records.front().machine.name, std::optional<QString>("VMC-7"));
    QCOMPARE(result.machines, (QStringList{"DMU 50", "VMC-7"}));  // the record without one adds none
    QCOMPARE(result.tools, (QStringList{"R1", "R2"}));
    QCOMPARE(result.total, 3);
    QVERIFY(!result.location.contains('?'));
    // Machine and tool together, then the MRR band [2, 4] cm³/s with the machine DMU 50.
    request.tool = "R2";
    client.loadHistory(location, request);
    QVERIFY(QTest::qWaitFor([&] { return client.idle(); }, 30000));
    QCOMPARE(loaded.last().at(1).value<LearningHistoryResult>().records.size(), std::size_t(0));
    request = {};
    request.machine = "DMU 50";
    request.mrr_lo = 2.0;
    request.mrr_hi = 4.0;
    client.loadHistory(location, request);
    QVERIFY(QTest::qWaitFor([&] { return client.idle(); }, 30000));
    const auto band = loaded.last().at(1).value<LearningHistoryResult>();
    QCOMPARE(band.records.size(), std::size_t(1));
    QCOMPARE(band.records.front().tool.id, QString("R2"));
    // What the worker wrote, read here on this thread through a connection of its own.
    mx::app::LearningDatabase db(location, mx::app::LearningDatabase::OpenMode::ExistingOnly);
    QCOMPARE(db.count(), 3);
  }

  // The worker reopens when the location changes; an unusable location fails the query, not the client.
  void newLocationAndErrors() {
    LearningClient client;
    QSignalSpy loaded(&client, &LearningClient::historyLoaded);
    QSignalSpy failed(&client, &LearningClient::historyFailed);
    QSignalSpy recordFailed(&client, &LearningClient::recordFailed);
    const QString a = dir_.filePath("a.sqlite"), b = dir_.filePath("b.sqlite");
    client.record(a, record("R1", QString("VMC-7"), 1.0));
    client.loadHistory(b, {});
    QVERIFY(QTest::qWaitFor([&] { return client.idle(); }, 10000));
    QCOMPARE(loaded.last().at(1).value<LearningHistoryResult>().total, 0);
    QCOMPARE(loaded.last().at(1).value<LearningHistoryResult>().location, b);
    const QString folder = dir_.filePath("a.sqlite");  // a file where a folder is expected
    client.record(folder + "/x.sqlite", record("R1", std::nullopt, 1.0));
    client.loadHistory(folder + "/x.sqlite", {});
    QVERIFY(QTest::qWaitFor([&] { return client.idle(); }, 10000));
    QCOMPARE(recordFailed.count(), 1);
    QCOMPARE(failed.count(), 1);
    QVERIFY2(failed.at(0).at(1).toString().contains(folder), qPrintable(failed.at(0).at(1).toString()));
    client.loadHistory(a, {});
    QVERIFY(QTest::qWaitFor([&] { return client.idle(); }, 10000));
    QCOMPARE(loaded.last().at(1).value<LearningHistoryResult>().total, 1);
  }

  void newerHistoryMakesTheOlderStale() {
    const QString location = dir_.filePath("stale.sqlite");
    LearningClient client;
    QSignalSpy loaded(&client, &LearningClient::historyLoaded);
    for (int i = 0; i < 5; ++i) client.record(location, record("R1", QString("M%1").arg(i), 1.0 + i));
    client.loadHistory(location, {});
    LearningHistoryRequest newest;
    newest.machine = "M3";
    const quint64 last = client.loadHistory(location, newest);
    QVERIFY(QTest::qWaitFor([&] { return client.idle(); }, 10000));
    QCOMPARE(loaded.count(), 1);
    QCOMPARE(loaded.at(0).at(0).toULongLong(), last);
    QCOMPARE(loaded.at(0).at(1).value<LearningHistoryResult>().records.size(), std::size_t(1));
  }

  void connectionTest_data() {
    QTest::addColumn<bool>("postgres");
    QTest::newRow("sqlite") << false;
    QTest::newRow("postgresql") << true;
  }
  void connectionTest() {
    QFETCH(bool, postgres);
    const QString location = newDatabase(postgres, "tested");
    if (location.isEmpty()) return;
    LearningClient client;
    client.record(location, record("R1", QString("VMC-7"), 1.0));
    client.record(location, record("R2", QString("VMC-7"), 1.0));
    QVERIFY(QTest::qWaitFor([&] { return client.idle(); }, 30000));
    QSignalSpy tested(&client, &LearningClient::tested);
    const quint64 generation = client.testConnection(location);
    QVERIFY(tested.wait(30000));
    QCOMPARE(tested.at(0).at(0).toULongLong(), generation);
    QCOMPARE(tested.at(0).at(1).toBool(), true);
    const QString shown = mx::app::parseLearningLocation(location).display();
    QCOMPARE(tested.at(0).at(2).toString(), QString("Connected to %1: schema 2, 2 records").arg(shown));
  }

  void connectionTestFailures() {
    LearningClient client;
    QSignalSpy tested(&client, &LearningClient::tested);
    // A missing file is reported, not created.
    const QString missing = dir_.filePath("new/learning.sqlite");
    client.testConnection(missing);
    QVERIFY(tested.wait(10000));
    QCOMPARE(tested.last().at(1).toBool(), true);
    QCOMPARE(tested.last().at(2).toString(),
             QString("No file yet at %1: it is created with the first recorded point").arg(missing));
    QVERIFY(!QFileInfo::exists(missing));
    // Not a database: named with its path.
    const QString junk = dir_.filePath("junk.sqlite");
    QFile f(junk);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QByteArray(4096, 'x'));
    f.close();
    client.testConnection(junk);
    QVERIFY(tested.wait(10000));
    QCOMPARE(tested.last().at(1).toBool(), false);
    QVERIFY2(tested.last().at(2).toString().contains(junk), qPrintable(tested.last().at(2).toString()));
    // Nothing listening: fails fast, naming the URL.
    const QString refused = QString("postgresql://planner@127.0.0.1:%1/learning").arg(mx::test::freeLoopbackPort());
    client.testConnection(refused);
    QVERIFY(tested.wait(10000));
    QCOMPARE(tested.last().at(1).toBool(), false);
    QVERIFY2(tested.last().at(2).toString().contains(refused), qPrintable(tested.last().at(2).toString()));
  }

  // A server that accepts and never answers holds the test for its connect_timeout (2 s) on the test
  // pool: the GUI thread never spends more than 100 ms on one event meanwhile, a newer test answers
  // first and the older one's answer is dropped.
  void hangingServerKeepsTheGuiResponsive() {
    const mx::test::LoopbackPort silent(mx::test::LoopbackPort::Mode::Listening);
    QVERIFY(silent.port() > 0);
    const QString hanging = QString("postgresql://planner@127.0.0.1:%1/learning?connect_timeout=2").arg(silent.port());
    LearningClient client;
    QSignalSpy tested(&client, &LearningClient::tested);
    mx::test::EventLoopProbe probe;
    QElapsedTimer clock;
    quint64 first = 0, second = 0;
    QTimer::singleShot(0, &client, [&] {
      clock.start();
      first = client.testConnection(hanging);
    });
    QTest::qWait(600);
    QCOMPARE(tested.count(), 0);  // still connecting
    QTimer::singleShot(0, &client, [&] { second = client.testConnection(hanging); });
    QVERIFY(tested.wait(15000));
    const qint64 answered_ms = clock.elapsed();
    QCOMPARE(tested.count(), 1);
    QCOMPARE(tested.at(0).at(0).toULongLong(), second);
    QCOMPARE(tested.at(0).at(1).toBool(), false);
    QVERIFY2(answered_ms >= 2000, qPrintable(QString::number(answered_ms)));  // it did wait for the server
    QTest::qWait(500);  // the first test has ended by now: its answer is stale
    QCOMPARE(tested.count(), 1);
    QVERIFY(first != 0 && first < second);
    QVERIFY2(probe.longestMs() < 100 * MX_TIMING_SCALE,
             qPrintable(QString("%1 ms in %2").arg(probe.longestMs()).arg(probe.longestEvent())));
    // Records do not wait for the test pool.
    const QString location = dir_.filePath("while_testing.sqlite");
    client.testConnection(hanging);
    QElapsedTimer recording;
    recording.start();
    client.record(location, record("R1", QString("VMC-7"), 1.0));
    QVERIFY(QTest::qWaitFor([&] { return client.idle(); }, 10000));
    QVERIFY2(recording.elapsed() < 1500, qPrintable(QString::number(recording.elapsed())));
  }
};

MX_REGISTER_TEST(TestLearningClient)
#include "test_learning_client.moc"
