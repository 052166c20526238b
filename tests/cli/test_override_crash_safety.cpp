// Crash safety of the override export (docs/reliability.md, "Crash safety"): `millexpert-cli override
// PROGRAM PROJECT --out OUT` is killed with SIGKILL while it writes OUT. The write is a small part of a
// run, so each kill is aimed: the test polls the process's open files until it holds one in OUT's folder
// (the temporary file of the atomic write), then waits a random time (fixed seed) up to 1.5 times as long
// as the write was measured to take in three complete runs of the build at hand, and kills it; a run that
// finishes first shrinks that bound by a fifth (the measurement may have caught a slow write). Runs
// alternate between two spindle speeds, so consecutive outputs differ. After every kill OUT is
// byte-identical to its content before the run or to the complete new output (its "(date: ...)" header
// line aside, which changes by the second).
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <algorithm>
#include <random>
#include <vector>

#include "support/kill_loop.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx;

namespace {

constexpr int kKills = 40;
constexpr unsigned kSeed = 20240501;
constexpr int kCalibrationRuns = 3;
constexpr qint64 kMinMaxDelayUs = 200;
const QString kProgram = MX_TEST_DATA_DIR "/gcode/pocket_mm.nc";
using mx::test::kSdnrp;
const QStringList kSpeeds{"3000", "4500"};

QStringList overrideArgs(const QString& out, int run) {
  return {"override", kProgram, kSdnrp, "--out", out, "--speed", kSpeeds[run % 2]};
}

QByteArray dateless(const QByteArray& text) {
  static const QRegularExpression date(R"(\(date: [^)\n]*\))");
  return QString::fromUtf8(text).replace(date, "(date: -)").toUtf8();
}

}  // namespace

class TestOverrideCrashSafety : public QObject {
  Q_OBJECT

  // The median time [us] for which complete runs hold the output's temporary file open, over the first
  // kCalibrationRuns runs in which the polling sees it (a loaded machine can finish a short write between
  // two polls); -1 when none of kCalibrationRuns * 4 runs shows it.
  static qint64 medianWriteMicros(const QString& folder, const QString& out) {
    std::vector<qint64> times;
    for (int run = 0; run < 4 * kCalibrationRuns && static_cast<int>(times.size()) < kCalibrationRuns; ++run) {
      QProcess cli;
      cli.start(MX_CLI_PATH, overrideArgs(out, run));
      const qint64 us = test::measureOpenMicros(cli, folder, 60000);
      cli.waitForFinished(60000);
      QFile::remove(out);
      if (us >= 0) times.push_back(us);
    }
    if (times.empty()) return -1;
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
  }

 private slots:
  void killedExportsLeaveTheOldOrTheNewProgram() {
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath("ref") && QDir(dir.path()).mkpath("out"));
    QByteArray refs[2];
    for (int run = 0; run < 2; ++run) {
      const QString ref = dir.filePath(QString("ref/%1.nc").arg(run));
      QProcess cli;
      cli.start(MX_CLI_PATH, overrideArgs(ref, run));
      QVERIFY(cli.waitForFinished(60000));
      QVERIFY2(cli.exitStatus() == QProcess::NormalExit && cli.exitCode() == 0, cli.readAllStandardError());
      refs[run] = test::readBytes(ref);
    }
    QVERIFY(dateless(refs[0]) != dateless(refs[1]));
    const QString folder = dir.filePath("out"), out = folder + "/program.nc";
    const qint64 write_us = medianWriteMicros(folder, out);
    QVERIFY2(write_us >= 0, "override --out never held its output's temporary file open");
    QVERIFY(QFile::copy(dir.filePath("ref/1.nc"), out));

    std::mt19937 random(kSeed);
    double max_delay_us = static_cast<double>(std::max(kMinMaxDelayUs, write_us * 3 / 2));
    std::uniform_real_distribution<double> fraction(0.0, 1.0);
    int runs = 0, kills = 0, in_write = 0, old_kept = 0, new_written = 0, finished = 0, stray = 0;
    QElapsedTimer clock;
    clock.start();
    while (kills < kKills && runs < 8 * kKills) {
      const int run = runs++;
      const QByteArray before = test::readBytes(out);
      QProcess cli;
      cli.start(MX_CLI_PATH, overrideArgs(out, run));
      QVERIFY(cli.waitForStarted(10000));
      const bool writing = test::waitForOpenFileBelow(cli, folder, 60000);
      const double delay_us = fraction(random) * max_delay_us;
      if (writing) test::spinFor(static_cast<qint64>(delay_us));
      const test::KillOutcome kill = test::stopAndKill(cli, folder);
      const QByteArray after = test::readBytes(out);
      if (!kill.killed) {
        ++finished;
        max_delay_us = std::max(static_cast<double>(kMinMaxDelayUs), 0.8 * max_delay_us);
        QCOMPARE(cli.exitCode(), 0);
        QCOMPARE(dateless(after), dateless(refs[run % 2]));
      } else {
        ++kills;
        in_write += kill.open_files.isEmpty() ? 0 : 1;
        const bool kept = after == before, written = dateless(after) == dateless(refs[run % 2]);
        QVERIFY2(kept || written, qPrintable(QString("kill %1: %2 is neither the old nor the new program (%3 bytes)")
                                                 .arg(kills)
                                                 .arg(out)
                                                 .arg(after.size())));
        ++(kept ? old_kept : new_written);
        // A kill after the write (the new program in place, nothing open) aimed too late, as a finished
        // run did: the process's own exit (LeakSanitizer's scan under ASan) outlasts the write.
        if (kill.open_files.isEmpty() && written && !kept)
          max_delay_us = std::max(static_cast<double>(kMinMaxDelayUs), 0.8 * max_delay_us);
      }
      for (const QString& name : QDir(folder).entryList(QDir::Files | QDir::Hidden))
        if (name != "program.nc") stray += QFile::remove(folder + "/" + name) ? 1 : 0;
    }
    qInfo(
        "override --out: write %lld us; %d runs, %d kills, %d with the output's temporary file open: old program "
        "kept %d, new program %d; %d runs finished first; stray temporary files %d; %lld ms",
        static_cast<long long>(write_us), runs, kills, in_write, old_kept, new_written, finished, stray,
        static_cast<long long>(clock.elapsed()));
    QCOMPARE(kills, kKills);
    QVERIFY2(in_write >= kKills / 2, qPrintable(QString("%1 kills during the write").arg(in_write)));
  }
};

MX_REGISTER_TEST(TestOverrideCrashSafety)
#include "test_override_crash_safety.moc"
