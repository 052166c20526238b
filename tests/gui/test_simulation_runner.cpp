// SimulationRunner: the simulation job on a one-thread engine pool streams a copy of each revolution to
// the GUI thread while it runs, delivers only the newest generation, and keeps the event loop free.
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QThreadPool>
#include <QTimer>
#include <cmath>
#include <vector>

#include "simulation_runner.h"
#include "support/fixtures.h"
#include "test_registry.h"

using mx::gui::SimulationChunkData;
using mx::gui::SimulationRunner;
using mx::gui::SimulationSummary;

namespace {
// q* of seed-reading.md: R1 at 5800 rpm, 0.4924 mm, 0.2722 mm/tooth (peak power 732.66 W, stable).
using mx::test::kRubioQStar;
constexpr double kMaxRevPerS = 12000.0 / 60.0;

mx::SimulationOptions liveOptions(int revolutions = 60) {
  mx::SimulationOptions o;
  o.revolutions = revolutions;
  o.evaluated_revolutions = 20;
  return o;
}

// Everything the runner emits, in order.
struct Recorder {
  std::vector<quint64> chunk_generations;
  std::vector<int> chunk_revolutions;
  std::vector<quint64> finished_generations;
  std::vector<SimulationSummary> summaries;
  std::vector<QString> failures;
  int chunks_before_finished = -1;
  bool chunk_while_idle = false;

  explicit Recorder(SimulationRunner& runner) {
    QObject::connect(&runner, &SimulationRunner::chunkReady, &runner,
                     [this, &runner](quint64 g, const SimulationChunkData& c) {
                       chunk_generations.push_back(g);
                       chunk_revolutions.push_back(c.revolution);
                       chunk_while_idle = chunk_while_idle || !runner.busy();
                     });
    QObject::connect(&runner, &SimulationRunner::finished, &runner, [this](quint64 g, const SimulationSummary& s) {
      if (chunks_before_finished < 0) chunks_before_finished = static_cast<int>(chunk_generations.size());
      finished_generations.push_back(g);
      summaries.push_back(s);
    });
    QObject::connect(&runner, &SimulationRunner::failed, &runner,
                     [this](quint64, const QString& m) { failures.push_back(m); });
  }
};
}  // namespace

class TestSimulationRunner : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { pool_.setMaxThreadCount(1); }

  void stablePointStreamsChunksThenSummary() {
    SimulationRunner runner(&pool_);
    QCOMPARE(runner.regenerativePasses(), 4);
    Recorder rec(runner);
    QSignalSpy busy(&runner, &SimulationRunner::busyChanged);
    QSignalSpy progress(&runner, &SimulationRunner::progress);
    const quint64 g = runner.submit(mx::test::rubioR1(), kRubioQStar, liveOptions(), 15000.0, kMaxRevPerS);
    QVERIFY(runner.busy());
    QTRY_COMPARE_WITH_TIMEOUT(rec.finished_generations.size(), std::size_t{1}, 60000);
    QCOMPARE(rec.finished_generations.front(), g);
    QVERIFY(rec.failures.empty());
    // One chunk per revolution, all before the summary, in order, while the job was running.
    QCOMPARE(rec.chunks_before_finished, 60);
    QVERIFY(!rec.chunk_while_idle);
    for (std::size_t i = 0; i < rec.chunk_revolutions.size(); ++i) {
      QCOMPARE(rec.chunk_revolutions[i], static_cast<int>(i) + 1);
      QCOMPARE(rec.chunk_generations[i], g);
    }
    QVERIFY(!runner.busy());
    QCOMPARE(busy.size(), 2);
    QCOMPARE(busy.at(0).at(0).toBool(), true);
    QCOMPARE(busy.at(1).at(0).toBool(), false);
    QCOMPARE(progress.last().at(0).toDouble(), 1.0);

    const SimulationSummary& s = rec.summaries.front();
    QVERIFY2(std::abs(s.peak_power_w / 732.66 - 1.0) < 0.01, qPrintable(QString::number(s.peak_power_w)));
    QVERIFY(!s.chatter);
    QVERIFY(!s.chatter_frequency_hz);
    QVERIFY(!s.suggested_rpm);
    QVERIFY(s.eta < 1.3);
    QVERIFY(s.chip_ratio < 1.25);
    QCOMPARE(s.tooth_passing_hz, 290.0);
    QCOMPARE(s.spindle_rpm, 5800.0);
    QCOMPARE(s.teeth, 3);
    QVERIFY(!s.power_limit_exceeded);
    QVERIFY(s.peak_force_n > 0.0);
    // Spectrum of the evaluated window: at least up to 5 f_tp, largest line at a tooth-passing harmonic.
    QVERIFY(s.spectrum_hz.size() > 50);
    QCOMPARE(s.spectrum_hz.size(), s.spectrum_n.size());
    QVERIFY(s.spectrum_hz.back() >= 5.0 * 290.0 - 10.0);
    qsizetype top = 1;
    for (qsizetype i = 1; i < s.spectrum_n.size(); ++i)
      if (s.spectrum_n[i] > s.spectrum_n[top]) top = i;
    const double h = s.spectrum_hz[top] / 290.0;
    QVERIFY2(std::abs(h - std::round(h)) < 0.05, qPrintable(QString::number(s.spectrum_hz[top])));
  }

  void powerLimitIsReported() {
    SimulationRunner runner(&pool_);
    Recorder rec(runner);
    runner.submit(mx::test::rubioR1(), kRubioQStar, liveOptions(30), 500.0, kMaxRevPerS);
    QTRY_COMPARE_WITH_TIMEOUT(rec.summaries.size(), std::size_t{1}, 60000);
    QVERIFY(rec.summaries.front().power_limit_exceeded);
    QCOMPARE(rec.summaries.front().spindle_power_limit_w, 500.0);
  }

  void newSubmissionCancelsTheRunningOne() {
    SimulationRunner runner(&pool_);
    Recorder rec(runner);
    const quint64 first = runner.submit(mx::test::rubioR1(), kRubioQStar, liveOptions(2000), 15000.0, kMaxRevPerS);
    QTRY_VERIFY_WITH_TIMEOUT(!rec.chunk_generations.empty(), 60000);  // the first job is running
    const std::size_t chunks_of_first = rec.chunk_generations.size();
    const quint64 second = runner.submit(mx::test::rubioR1(), kRubioQStar, liveOptions(), 15000.0, kMaxRevPerS);
    QVERIFY(second != first);
    QTRY_COMPARE_WITH_TIMEOUT(rec.finished_generations.size(), std::size_t{1}, 60000);
    QTRY_VERIFY_WITH_TIMEOUT(!runner.busy(), 60000);  // the cancelled job has ended as well
    QTest::qWait(50);
    QCOMPARE(rec.finished_generations, std::vector<quint64>{second});
    for (std::size_t i = chunks_of_first; i < rec.chunk_generations.size(); ++i)
      QCOMPARE(rec.chunk_generations[i], second);
    QCOMPARE(rec.chunk_generations.size() - chunks_of_first, std::size_t{60});
    QVERIFY(rec.failures.empty());
  }

  void cancelDropsEverything() {
    SimulationRunner runner(&pool_);
    Recorder rec(runner);
    QSignalSpy busy(&runner, &SimulationRunner::busyChanged);
    runner.submit(mx::test::rubioR1(), kRubioQStar, liveOptions(2000), 15000.0, kMaxRevPerS);
    QTRY_VERIFY_WITH_TIMEOUT(!rec.chunk_generations.empty(), 60000);
    runner.cancel();
    const std::size_t chunks = rec.chunk_generations.size();
    QTRY_VERIFY_WITH_TIMEOUT(!runner.busy(), 60000);
    QCOMPARE(rec.chunk_generations.size(), chunks);
    QVERIFY(rec.finished_generations.empty());
    QVERIFY(rec.failures.empty());
    QCOMPARE(busy.last().at(0).toBool(), false);
  }

  void chatteringPointSuggestsSmithTlustySpeed() {
    SimulationRunner runner(&pool_);
    Recorder rec(runner);
    const mx::OperatingPoint point{5800.0 / 60.0, 3e-3, 0.1e-3};
    runner.submit(mx::test::rubioR1(), point, liveOptions(), 15000.0, kMaxRevPerS);
    QTRY_COMPARE_WITH_TIMEOUT(rec.summaries.size(), std::size_t{1}, 60000);
    const SimulationSummary& s = rec.summaries.front();
    qInfo("eta %.3f, chip ratio %.3f, f_c %.2f Hz, suggested %.1f rpm (k = %d)", s.eta, s.chip_ratio,
          s.chatter_frequency_hz.value_or(-1.0), s.suggested_rpm.value_or(-1.0), s.suggested_k);
    QVERIFY(s.chatter);
    QVERIFY(s.eta >= 1.3);
    QVERIFY(!s.diverged);  // K = 4 bounds the amplitude
    QVERIFY(s.chatter_frequency_hz);
    const double fc = *s.chatter_frequency_hz;
    QVERIFY(fc > 500.0 && fc < 800.0);  // near the R1 modes (603, 666 Hz)
    QVERIFY(s.suggested_rpm);
    const double n_rpm = *s.suggested_rpm;
    QVERIFY(n_rpm > 0.0 && n_rpm <= 12000.0);
    const double k = 60.0 * fc / (3.0 * n_rpm);
    QVERIFY2(std::abs(k - std::round(k)) < 1e-9, qPrintable(QString::number(k, 'g', 15)));
    QCOMPARE(static_cast<int>(std::lround(k)), s.suggested_k);
    QVERIFY(s.a_chatter_n > 0.0);
    QVERIFY(!s.spectrum_hz.isEmpty() && s.spectrum_hz.back() >= fc);
  }

  void suggestedSpeedRespectsTheMachineMaximum() {
    SimulationRunner runner(&pool_);
    Recorder rec(runner);
    const mx::OperatingPoint point{5800.0 / 60.0, 3e-3, 0.1e-3};
    runner.submit(mx::test::rubioR1(), point, liveOptions(), 15000.0, 4000.0 / 60.0);
    QTRY_COMPARE_WITH_TIMEOUT(rec.summaries.size(), std::size_t{1}, 60000);
    const SimulationSummary& s = rec.summaries.front();
    QVERIFY(s.chatter && s.suggested_rpm);
    QVERIFY(*s.suggested_rpm <= 4000.0 + 1e-9);
  }

  void invalidInputFails() {
    SimulationRunner runner(&pool_);
    Recorder rec(runner);
    const quint64 g = runner.submit(mx::test::rubioR1(), {0.0, 1e-3, 1e-4}, liveOptions(), 15000.0, kMaxRevPerS);
    QSignalSpy failed(&runner, &SimulationRunner::failed);
    QVERIFY(failed.wait(20000));
    QCOMPARE(failed.first().at(0).toULongLong(), g);
    QVERIFY(failed.first().at(1).toString().contains("speed"));
    QVERIFY(rec.finished_generations.empty());
    QTRY_VERIFY(!runner.busy());
  }

  void regenerativePassesSetter() {
    SimulationRunner runner(&pool_);
    runner.setRegenerativePasses(1);
    QCOMPARE(runner.regenerativePasses(), 1);
    runner.setRegenerativePasses(100);
    QVERIFY(runner.regenerativePasses() <= 8);
  }

  // The GUI thread stays responsive: a 10 ms timer keeps ticking while a long run streams its chunks.
  void eventLoopKeepsTickingDuringALongRun() {
    SimulationRunner runner(&pool_);
    Recorder rec(runner);
    int ticks = 0, ticks_while_streaming = 0;
    QTimer timer;
    timer.setTimerType(Qt::PreciseTimer);
    timer.setInterval(10);
    connect(&timer, &QTimer::timeout, this, [&] {
      ++ticks;
      if (!rec.chunk_generations.empty() && rec.finished_generations.empty()) ++ticks_while_streaming;
    });
    QElapsedTimer clock;
    clock.start();
    timer.start();
    mx::SimulationOptions options = liveOptions(6000);
    options.record_every = 4;  // ~23 MB of trace
    runner.submit(mx::test::rubioR1(), kRubioQStar, options, 15000.0, kMaxRevPerS);
    QTRY_COMPARE_WITH_TIMEOUT(rec.finished_generations.size(), std::size_t{1}, 120000);
    const qint64 elapsed_ms = clock.elapsed();
    timer.stop();
    qInfo("6000 revolutions: %lld ms, %d ticks (%d while streaming), %zu chunks", elapsed_ms, ticks,
          ticks_while_streaming, rec.chunk_generations.size());
    QCOMPARE(rec.chunk_generations.size(), std::size_t{6000});
    QVERIFY(elapsed_ms >= 100);  // long enough for the check to mean something
    QVERIFY2(ticks > 0.5 * static_cast<double>(elapsed_ms) / 10.0, qPrintable(QString::number(ticks)));
    QVERIFY(ticks_while_streaming > 0);  // chunks arrived while the job was still running
  }

 private:
  QThreadPool pool_;
};

MX_REGISTER_TEST(TestSimulationRunner)
#include "test_simulation_runner.moc"
