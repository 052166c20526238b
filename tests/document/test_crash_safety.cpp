// Crash safety of project saves and autosaves (docs/reliability.md, "Crash safety"): document_writer
// saves, or autosaves, in a loop through ProjectDocument as the GUI does, and is killed with SIGKILL at
// random times (fixed seed). After every kill the written file is byte-identical to its content before
// the interrupted write or to the content being written, it loads and validates, and after an autosave
// kill recovery offers the autosave and restores it. The kills must land inside the writes: the test
// counts those that stopped the writer between its "begin" and "end" lines, and requires a minimum.
// Serialising dominates a write, so random delays seldom find the temporary file open (under the
// sanitizers almost never); every kAimEvery-th kill is therefore aimed: it polls the writer's open
// files and kills as soon as it holds one in the folder.
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <algorithm>
#include <memory>
#include <random>

#include "document/project.h"
#include "document/project_document.h"
#include "support/kill_loop.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx;

namespace {

constexpr int kKills = 40;
constexpr unsigned kSeed = 20240501;
constexpr int kMaxDelayUs = 40000;  // after "ready"; one write takes a few ms (release build)
constexpr int kDelayWrites = 3;     // ... or over this many writes of the build at hand (sanitizers)
constexpr int kAimEvery = 4;
const QString kProject = MX_PROJECTS_DIR "/library-20-tools.mxproj";

struct Tally {
  int kills = 0;
  int in_write = 0;     // stopped between "begin k" and "end k"
  int temp_open = 0;    // with a temporary file of the write open
  int old_kept = 0;     // the file still held its content from before the interrupted write
  int new_written = 0;  // the file held the content being written
  int stray = 0;        // temporary files left next to the file (complete copies, never the file)
  QString failure;      // the first broken expectation; the loop stops there
};

QProcess* startWriter(const QString& mode, const QString& project, const QStringList& extra = {}) {
  auto* writer = new QProcess;
  writer->start(MX_DOCUMENT_WRITER_PATH, QStringList{mode, project} + extra);
  return writer;
}

// Runs the writer to the end (`count` writes) and returns the content of `written`; empty on failure.
QByteArray writeToCompletion(const QString& mode, const QString& project, int count, const QString& written) {
  std::unique_ptr<QProcess> writer(startWriter(mode, project, {QString::number(count)}));
  if (!writer->waitForFinished(30000) || writer->exitStatus() != QProcess::NormalExit || writer->exitCode() != 0) {
    qWarning("document_writer %s failed: %s", qPrintable(mode), writer->readAllStandardError().constData());
    return {};
  }
  return test::readBytes(written);
}

// The k of a "begin k" or "end k" line; -1 for anything else.
long long indexOf(const QByteArray& line, const QByteArray& word) {
  return line.startsWith(word + ' ') ? line.mid(word.size() + 1).toLongLong() : -1;
}

// Files in `folder` other than `expected`, removed so that each kill is counted once.
int removeStrays(const QString& folder, const QStringList& expected) {
  int stray = 0;
  for (const QString& name : QDir(folder).entryList(QDir::Files | QDir::Hidden))
    if (!expected.contains(name)) stray += QFile::remove(QDir(folder).filePath(name)) ? 1 : 0;
  return stray;
}

}  // namespace

class TestCrashSafety : public QObject {
  Q_OBJECT

  // Kills `mode` writers kKills times; `written` is the file they write, `variants` its two contents.
  // `check` runs after each kill's byte comparison and returns what is wrong ("" when nothing).
  template <typename Check>
  Tally killLoop(const QString& mode, const QString& project, const QString& written, const QByteArray (&variants)[2],
                 Check check) {
    const QString folder = QFileInfo(written).absolutePath();
    const QStringList expected{QFileInfo(project).fileName(), QFileInfo(written).fileName()};
    Tally tally;
    std::unique_ptr<QProcess> calibration(startWriter(mode, project));
    const qint64 write_us = test::calibrateWriteMicros(*calibration, folder, kDelayWrites, 60000);
    if (write_us < 0) {
      tally.failure = "document_writer did not complete its first writes: " +
                      QString::fromLocal8Bit(calibration->readAllStandardError());
      return tally;
    }
    const auto max_delay_us = static_cast<int>(std::max<qint64>(kMaxDelayUs, kDelayWrites * write_us));
    removeStrays(folder, expected);  // what the calibration's kill left; each kill below reads the file anew
    std::mt19937 random(kSeed);
    std::uniform_int_distribution<int> delay_us(0, max_delay_us);
    while (tally.kills < kKills) {
      const QByteArray before = test::readBytes(written);
      std::unique_ptr<QProcess> writer(startWriter(mode, project));
      QByteArray seen;
      if (!test::waitForLine(*writer, seen, "ready", 30000)) {
        tally.failure = "document_writer did not start: " + QString::fromLocal8Bit(writer->readAllStandardError());
        break;
      }
      const int delay = delay_us(random);  // drawn for every kill, so that the random kills stay as seeded
      if (tally.kills % kAimEvery == kAimEvery - 1) {
        test::waitForOpenFileBelow(*writer, folder, 30000);
      } else {
        test::spinFor(delay);
      }
      const test::KillOutcome kill = test::stopAndKill(*writer, folder, seen);
      if (!kill.killed) {
        tally.failure =
            "document_writer ended before the kill: " + QString::fromLocal8Bit(writer->readAllStandardError());
        break;
      }
      ++tally.kills;

      const long long begun = indexOf(kill.last_line, "begin"), ended = indexOf(kill.last_line, "end");
      QList<QByteArray> allowed;
      if (ended >= 0) {
        allowed = {variants[ended % 2]};
      } else if (begun >= 0) {
        allowed = {begun == 0 ? before : variants[(begun - 1) % 2], variants[begun % 2]};
        ++tally.in_write;
      } else {
        allowed = {before};  // killed before its first write
      }
      for (const QString& file : kill.open_files) tally.temp_open += file != written && file != project ? 1 : 0;
      const QByteArray after = test::readBytes(written);
      if (!allowed.contains(after)) {
        tally.failure = QString("kill %1 (last line '%2'): %3 is neither the old nor the new content (%4 bytes)")
                            .arg(tally.kills)
                            .arg(QString::fromLatin1(kill.last_line), written)
                            .arg(after.size());
        break;
      }
      if (begun >= 0) ++(after == allowed.last() ? tally.new_written : tally.old_kept);
      try {
        app::loadProject(written);  // parses and validates
      } catch (const app::ProjectError& e) {
        tally.failure = QString("kill %1: %2").arg(tally.kills).arg(e.what());
        break;
      }
      tally.failure = check();
      if (!tally.failure.isEmpty()) break;
      tally.stray += removeStrays(folder, expected);
    }
    return tally;
  }

  static void report(const char* kind, const Tally& t, qint64 ms) {
    qInfo(
        "%s: %d kills, %d inside a write (%d with its temporary file open): old content kept %d, new content %d; "
        "stray temporary files %d; %lld ms",
        kind, t.kills, t.in_write, t.temp_open, t.old_kept, t.new_written, t.stray, static_cast<long long>(ms));
  }

 private slots:
  void killedSavesLeaveTheOldOrTheNewFile() {
    QTemporaryDir dir;
    const QString path = dir.filePath("p.mxproj");
    QVERIFY(QFile::copy(kProject, path));
    QFile(path).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
    const QByteArray variants[2] = {writeToCompletion("save", path, 1, path), writeToCompletion("save", path, 2, path)};
    QVERIFY(!variants[0].isEmpty() && !variants[1].isEmpty() && variants[0] != variants[1]);
    QElapsedTimer clock;
    clock.start();
    const Tally t = killLoop("save", path, path, variants, [] { return QString(); });
    report("project save", t, clock.elapsed());
    QVERIFY2(t.failure.isEmpty(), qPrintable(t.failure));
    QCOMPARE(t.kills, kKills);
    QVERIFY2(t.in_write >= kKills / 2, qPrintable(QString("%1 kills inside a write").arg(t.in_write)));
    QVERIFY2(t.temp_open >= 1, "no kill found a save's temporary file open");
  }

  void killedAutosavesLeaveARecoverableAutosave() {
    QTemporaryDir dir;
    const QString path = dir.filePath("p.mxproj"), autosave = path + ".autosave";
    QVERIFY(QFile::copy(kProject, path));
    QFile(path).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
    const QByteArray original = test::readBytes(path);
    const QByteArray variants[2] = {writeToCompletion("autosave", path, 1, autosave),
                                    writeToCompletion("autosave", path, 2, autosave)};
    QVERIFY(!variants[0].isEmpty() && !variants[1].isEmpty() && variants[0] != variants[1]);
    int recovered = 0;
    QElapsedTimer clock;
    clock.start();
    const Tally t = killLoop("autosave", path, autosave, variants, [&] {
      if (test::readBytes(path) != original) return QString("an autosave changed the project file");
      if (app::ProjectDocument::recoveryCandidate(path) != autosave) return QString("the autosave is not offered");
      app::ProjectDocument doc;
      doc.recover(path);  // loadProject above has shown that it loads
      if (!doc.isDirty() || app::projectToJson(doc.project()) != app::projectToJson(app::loadProject(autosave)))
        return QString("recovery did not restore the autosave");
      ++recovered;
      return QString();
    });
    report("autosave", t, clock.elapsed());
    QVERIFY2(t.failure.isEmpty(), qPrintable(t.failure));
    QCOMPARE(t.kills, kKills);
    QCOMPARE(recovered, kKills);
    QVERIFY2(t.in_write >= kKills / 2, qPrintable(QString("%1 kills inside a write").arg(t.in_write)));
    QVERIFY2(t.temp_open >= 1, "no kill found an autosave's temporary file open");
  }
};

MX_REGISTER_TEST(TestCrashSafety)
#include "test_crash_safety.moc"
