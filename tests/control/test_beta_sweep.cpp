// J_c(beta) sweep (the paper's figure 13): grid, stable-zero region, minimiser, agreement with single runs.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include "control/beta_sweep.h"
#include "core/cancellation.h"
#include "core/invalid_input.h"
#include "test_registry.h"

using namespace mx;

class TestBetaSweep : public QObject {
  Q_OBJECT
 private slots:
  void grid_data() {
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("to");
    QTest::addColumn<double>("step");
    QTest::addColumn<int>("count");
    QTest::addColumn<double>("last");
    QTest::newRow("[-1, 1] step 0.1") << -1.0 << 1.0 << 0.1 << 21 << 1.0;
    QTest::newRow("31 points") << -1.0 << 1.0 << 2.0 / 30.0 << 31 << 1.0;
    QTest::newRow("single") << 0.0 << 0.0 << 0.1 << 1 << 0.0;
    QTest::newRow("end appended") << -0.5 << 0.5 << 0.3 << 5 << 0.5;
  }
  void grid() {
    QFETCH(double, from);
    QFETCH(double, to);
    QFETCH(double, step);
    QFETCH(int, count);
    QFETCH(double, last);
    const std::vector<double> g = betaGrid(from, to, step);
    QCOMPARE(static_cast<int>(g.size()), count);
    QCOMPARE(g.front(), from);
    QCOMPARE(g.back(), last);
    for (double b : g) QVERIFY(b >= -1.0 && b <= 1.0);
    if (from < 0.0 && to > 0.0 && std::abs(std::remainder(from, step)) < 1e-12)
      QVERIFY(std::find(g.begin(), g.end(), 0.0) != g.end());  // exactly 0: the ZOH structure
  }
  void invalidGrid() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput, betaGrid(0.5, -0.5, 0.1));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, betaGrid(-1.5, 0.5, 0.1));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, betaGrid(-1.0, 1.0, 0.0));
  }

  void paperSweep() {
    AdaptiveControlSettings base;
    const auto t0 = std::chrono::steady_clock::now();
    const BetaSweepResult r = sweepBeta(base, {-1.0, 1.0, 2.0 / 30.0, 2});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    qInfo("31-point sweep: %.3f s", seconds);
    QCOMPARE(static_cast<int>(r.beta.size()), 31);
    for (std::size_t i = 0; i < r.beta.size(); ++i) {
      QCOMPARE(static_cast<bool>(r.unstable_zero[i]), r.beta[i] < -0.571987);  // threshold from zero_threshold
      QVERIFY(r.completed[i]);
      QVERIFY(std::isfinite(r.Jc_N_s[i]) && r.Jc_N_s[i] > 0.0);
    }
    QVERIFY(r.found);
    // Our minimiser over the stable-zero region is beta = 0.733 (J_c = 76.3 N s); the paper's figure 13 shows
    // about -0.3. Not reproduced: see docs/control-engine-notes.md.
    QVERIFY2(std::abs(r.best_beta - 0.7333) < 1e-3, qPrintable(QString::number(r.best_beta)));
    QVERIFY(std::abs(r.best_Jc_N_s - 76.34) < 0.02 * 76.34);
    // the sweep equals single runs (deterministic, thread-independent)
    for (std::size_t i : {std::size_t{10}, std::size_t{15}, std::size_t{30}}) {
      AdaptiveControlSettings s = base;
      s.beta = r.beta[i];
      QCOMPARE(simulateAdaptiveForceControl(s).metrics.Jc_N_s, r.Jc_N_s[i]);
    }
    QVERIFY(seconds < 20.0);  // the 2 s target is measured by bench_control, not asserted under CI load
  }

  void cancellation() {
    std::atomic<bool> cancel{true};
    JobControl job;
    job.cancel = &cancel;
    QVERIFY_THROWS_EXCEPTION(Cancelled, sweepBeta(AdaptiveControlSettings{}, {-0.2, 0.2, 0.1, 2}, job));
  }
};

MX_REGISTER_TEST(TestBetaSweep)
#include "test_beta_sweep.moc"
