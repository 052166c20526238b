// Crash safety of the Rule 14 learning database (docs/reliability.md, "Crash safety"): its connections run
// in WAL mode with synchronous = FULL, and learning_writer, killed with SIGKILL at random times (fixed
// seed) while it inserts, leaves after every kill a database whose PRAGMA integrity_check is "ok", whose
// rows are all complete (weight rows, checksums), that holds every insert the writer saw committed and at
// most the one in flight, and that still accepts writes. The kills must land inside the inserts: the
// test counts those that stopped the writer between its "begin" and "end" lines, and requires a minimum.
#include <QElapsedTimer>
#include <QFileInfo>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <algorithm>
#include <memory>
#include <random>

#include "services/learning_database.h"
#include "support/kill_loop.h"
#include "test_registry.h"

using mx::app::LearningDatabase;

namespace {

constexpr int kKills = 40;
constexpr unsigned kSeed = 20240501;
constexpr int kMaxDelayUs = 30000;  // after "ready"; one insert (an fsync) takes a few ms (release build)
constexpr int kDelayWrites = 3;     // ... or over this many inserts of the build at hand (sanitizers)

QVariant scalar(const LearningDatabase& db, const QString& sql) {
  QSqlQuery q(QSqlDatabase::database(db.connectionName(), false));
  if (!q.exec(sql) || !q.next()) return {};
  return q.value(0);
}

long long indexOf(const QByteArray& line, const QByteArray& word) {
  return line.startsWith(word + ' ') ? line.mid(word.size() + 1).toLongLong() : -1;
}

}  // namespace

class TestLearningCrashSafety : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;

 private slots:
  void walWithFullSynchronous() {
    const QString path = dir_.filePath("pragmas.sqlite");
    LearningDatabase db(path);
    QCOMPARE(scalar(db, "PRAGMA journal_mode").toString(), QString("wal"));
    QCOMPARE(scalar(db, "PRAGMA synchronous").toInt(), 2);  // FULL: each commit is on disk when insert returns
    LearningDatabase other(path, LearningDatabase::OpenMode::ExistingOnly);  // every connection, not just the first
    QCOMPARE(scalar(other, "PRAGMA journal_mode").toString(), QString("wal"));
    QCOMPARE(scalar(other, "PRAGMA synchronous").toInt(), 2);
  }

  void killedWritersLeaveAnIntactDatabase() {
    const QString path = dir_.filePath("killed.sqlite");
    { LearningDatabase create(path); }
    QProcess calibration;
    calibration.start(MX_LEARNING_WRITER_PATH, {path});
    const qint64 write_us = mx::test::calibrateWriteMicros(calibration, dir_.path(), kDelayWrites, 60000);
    QVERIFY2(write_us >= 0, calibration.readAllStandardError().constData());
    const qint64 calibration_rows = LearningDatabase(path, LearningDatabase::OpenMode::ExistingOnly).count();
    std::mt19937 random(kSeed);
    std::uniform_int_distribution<int> delay_us(
        0, static_cast<int>(std::max<qint64>(kMaxDelayUs, kDelayWrites * write_us)));
    qint64 rows = calibration_rows;
    int kills = 0, in_write = 0, in_flight_committed = 0, integrity_ok = 0;
    QElapsedTimer clock;
    clock.start();
    while (kills < kKills) {
      QProcess writer;
      writer.start(MX_LEARNING_WRITER_PATH, {path});
      QByteArray seen;
      QVERIFY2(mx::test::waitForLine(writer, seen, "ready", 30000), writer.readAllStandardError().constData());
      mx::test::spinFor(delay_us(random));
      const mx::test::KillOutcome kill = mx::test::stopAndKill(writer, dir_.path(), seen);
      QVERIFY2(kill.killed, writer.readAllStandardError().constData());
      ++kills;

      const long long begun = indexOf(kill.last_line, "begin"), ended = indexOf(kill.last_line, "end");
      LearningDatabase db(path, LearningDatabase::OpenMode::ExistingOnly);  // replays the WAL the kill left
      const mx::app::LearningConsistency c = db.checkConsistency();
      QCOMPARE(c.integrity, QString("ok"));
      ++integrity_ok;
      QVERIFY2(c.problems.isEmpty(), qPrintable(c.problems.join("\n")));
      const qint64 before = rows;
      rows = db.count();
      const QString state = QString("kill %1, last line '%2': %3 rows, %4 before")
                                .arg(kills)
                                .arg(QString::fromLatin1(kill.last_line))
                                .arg(rows)
                                .arg(before);
      if (ended >= 0) {
        QVERIFY2(rows == ended + 1, qPrintable(state));
      } else if (begun >= 0) {
        QVERIFY2(rows == begun || rows == begun + 1, qPrintable(state));
        ++in_write;
        in_flight_committed += rows == begun + 1 ? 1 : 0;
      } else {
        QVERIFY2(rows == before, qPrintable(state));  // killed before its first insert
      }
      // No gap and no duplicate: the writer indices are exactly 0..rows-1.
      QCOMPARE(scalar(db, "SELECT COUNT(DISTINCT json_extract(objectives_json, '$.writer_index')) FROM learning_entry")
                   .toLongLong(),
               rows);
      if (rows > 0)
        QCOMPARE(
            scalar(db, "SELECT MAX(json_extract(objectives_json, '$.writer_index')) FROM learning_entry").toLongLong(),
            rows - 1);
    }
    qInfo(
        "learning database: %d kills, %d inside an insert (%d of them with the row already in the WAL), "
        "integrity_check ok %d "
        "times, %lld rows; %lld ms",
        kills, in_write, in_flight_committed, integrity_ok, static_cast<long long>(rows),
        static_cast<long long>(clock.elapsed()));
    QVERIFY2(in_write >= kKills / 2, qPrintable(QString("%1 kills inside an insert").arg(in_write)));
    QVERIFY2(rows - calibration_rows >= kKills / 4, "the writers committed almost nothing: the kills came too early");

    QProcess writer;  // the file still takes writes after all the kills
    writer.start(MX_LEARNING_WRITER_PATH, {path, "1"});
    QVERIFY(writer.waitForFinished(30000));
    QCOMPARE(writer.exitCode(), 0);
    LearningDatabase db(path, LearningDatabase::OpenMode::ExistingOnly);
    QCOMPARE(db.count(), rows + 1);
    QVERIFY(db.checkConsistency().ok());
  }
};

MX_REGISTER_TEST(TestLearningCrashSafety)
#include "test_learning_crash_safety.moc"
