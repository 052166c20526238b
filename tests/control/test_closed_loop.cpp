// Adaptive force control over the paper's workpiece (figures 9-12: beta = -0.3, 0, 0.3, 1): invariants (feed
// limits, bounded force, eq. 28 residual, no NaN), exact depth changes, the metrics, cancellation.
#include <atomic>
#include <cmath>

#include "control/closed_loop.h"
#include "core/cancellation.h"
#include "core/invalid_input.h"
#include "test_registry.h"

using namespace mx;

class TestClosedLoop : public QObject {
  Q_OBJECT
 private slots:
  void paperWorkpiece_data() {
    QTest::addColumn<double>("beta");
    QTest::addColumn<double>("feed_max_mm_s");
    QTest::addColumn<double>("Jc");  // our measured J_c (N s), regression values (see docs/control-engine-notes.md)
    QTest::newRow("fig 9, beta = -0.3") << -0.3 << 30.0 << 172.29;
    QTest::newRow("fig 10, beta = 0") << 0.0 << 30.0 << 176.73;
    QTest::newRow("fig 11, beta = 0.3") << 0.3 << 30.0 << 109.14;
    QTest::newRow("fig 12, beta = 1") << 1.0 << 30.0 << 87.31;
    QTest::newRow("beta = 0, f_max 60 mm/s") << 0.0 << 60.0 << -1.0;
    QTest::newRow("beta = -0.5, f_max 20 mm/s") << -0.5 << 20.0 << -1.0;
  }
  void paperWorkpiece() {
    QFETCH(double, beta);
    QFETCH(double, feed_max_mm_s);
    QFETCH(double, Jc);
    AdaptiveControlSettings s;
    s.beta = beta;
    s.feed_max_m_s = feed_max_mm_s * 1e-3;
    const ClosedLoopResult r = simulateAdaptiveForceControl(s);
    const ClosedLoopMetrics& m = r.metrics;
    QVERIFY(m.completed);
    QCOMPARE(static_cast<int>(m.steps.size()), 3);
    QVERIFY(m.steps[0].upward && m.steps[1].upward && !m.steps[2].upward);  // 2->3, 3->5, 5->3 mm

    // depth changes where the integrated position crosses 5.87, 11.74, 17.61 mm
    for (int i = 0; i < 3; ++i) {
      const double t = r.depth_change_times_s[static_cast<std::size_t>(i)];
      for (const auto& p : r.dense)
        if (p.t == t) QVERIFY(std::abs(p.position_m - 5.87e-3 * (i + 1)) < 1e-9);
    }

    // invariants: feed within [0, f_max] (samples and the continuous hold output), force bounded by the largest
    // static force the drive can produce, no NaN
    const double bound = makeForcePlant(s.process, 5e-3).gain_N_s_per_m * s.feed_max_m_s;
    for (const auto& smp : r.samples) {
      QVERIFY(smp.feed_m_s >= 0.0 && smp.feed_m_s <= s.feed_max_m_s);
      QVERIFY(std::isfinite(smp.force_N) && std::isfinite(smp.model_N) && std::isfinite(smp.feed_unsaturated_m_s));
      for (double th : smp.theta) QVERIFY(std::isfinite(th));
      QVERIFY(smp.diophantine_residual < 1e-9);
    }
    for (const auto& p : r.dense) {
      QVERIFY(p.feed_command_m_s >= 0.0 && p.feed_command_m_s <= s.feed_max_m_s);
      QVERIFY(p.feed_actual_m_s >= -1e-12 && p.feed_actual_m_s <= s.feed_max_m_s * (1.0 + 1e-6));
      QVERIFY(std::isfinite(p.force_N));
      QVERIFY(p.force_N >= -1e-6 && p.force_N <= bound * (1.0 + 1e-6));
    }
    for (const auto& st : m.steps) {
      QVERIFY(st.peak_force_N <= bound * (1.0 + 1e-6));
      QVERIFY(std::isfinite(st.overshoot_pct) && st.overshoot_pct >= 0.0);
    }
    QVERIFY(m.max_feed_m_s <= s.feed_max_m_s && m.min_feed_m_s >= 0.0);
    QVERIFY(m.max_diophantine_residual < 1e-9);
    QVERIFY(!m.unstable_zero);

    // the continuous output passes through its samples, and the interpolation equals them there
    std::size_t matched = 0;
    for (const auto& smp : r.samples)
      for (const auto& p : r.dense)
        if (p.t == smp.t) {
          QCOMPARE(p.force_N, smp.force_N);
          QVERIFY(std::abs(p.interpolated_N - smp.force_N) <= 1e-9 * std::max(1.0, smp.force_N));
          ++matched;
        }
    QCOMPARE(matched, r.samples.size());

    // the force ends at the reference (within the 5 % band) and the drive pole at z = 0 was handled
    QVERIFY2(std::abs(r.samples.back().force_N - 1200.0) < 0.05 * 1200.0,
             qPrintable(QString::number(r.samples.back().force_N)));
    bool removed = false;
    for (const auto& smp : r.samples) removed = removed || smp.common_factors_removed > 0;
    QVERIFY(removed);
    QVERIFY(m.Jc_N_s > 0.0);
    if (Jc > 0.0) QVERIFY2(std::abs(m.Jc_N_s - Jc) < 0.02 * Jc, qPrintable(QString::number(m.Jc_N_s, 'f', 3)));
  }

  // The metrics on hand-made series: overshoot, undershoot, settling, J_c of a known ripple.
  void metricsOnKnownSeries() {
    ClosedLoopResult r;
    for (int k = 0; k <= 4; ++k) {
      ClosedLoopSample s;
      s.t = k * 1.0;
      s.force_N = 100.0;
      r.samples.push_back(s);
    }
    // continuous: 100 with a triangle bump of height 10 in [1, 2] (area 5), depth step up at t = 1 and down at 3
    for (int i = 0; i <= 40; ++i) {
      ClosedLoopDensePoint p;
      p.t = i * 0.1;
      p.force_N = 100.0 + (p.t > 1.0 && p.t < 2.0 ? 10.0 * (1.0 - std::abs(p.t - 1.5) / 0.5) : 0.0);
      if (i >= 30 && i <= 34) p.force_N = 80.0;  // a dip of 20 N from t = 3.0 to 3.4
      p.interpolated_N = 100.0;
      p.depth_m = i <= 10 ? 1e-3 : (i < 30 ? 2e-3 : 1e-3);
      r.dense.push_back(p);
    }
    r.depth_change_times_s = {r.dense[10].t, r.dense[30].t};
    const ClosedLoopMetrics m = closedLoopMetrics(r, 100.0, 0.05);
    QCOMPARE(static_cast<int>(m.steps.size()), 2);
    QVERIFY(std::abs(m.steps[0].overshoot_pct - 10.0) < 1e-9);
    QVERIFY(m.steps[0].upward && !m.steps[1].upward);
    QVERIFY(std::abs(m.steps[1].overshoot_pct - 20.0) < 1e-9);   // undershoot
    QVERIFY(std::abs(m.steps[0].settling_time_s - 0.7) < 1e-9);  // last point out of the 5 % band: t = 1.7
    QVERIFY(m.steps[0].settled);
    // trapezoid rule: bump 5 N s (exact for a piecewise-linear signal) + dip 20 N x 0.4 s + two edge triangles of 1 N s
    QVERIFY2(std::abs(m.Jc_N_s - 15.0) < 1e-9, qPrintable(QString::number(m.Jc_N_s, 'g', 12)));
  }

  void cancellation() {
    std::atomic<bool> cancel{true};
    JobControl job;
    job.cancel = &cancel;
    QVERIFY_THROWS_EXCEPTION(Cancelled, simulateAdaptiveForceControl(AdaptiveControlSettings{}, job));
  }

  void progressReported() {
    double last = -1.0;
    int calls = 0;
    JobControl job;
    job.progress = [&](double f) {
      QVERIFY(f >= last && f <= 1.0);
      last = f;
      ++calls;
    };
    simulateAdaptiveForceControl(AdaptiveControlSettings{}, job);
    QVERIFY(calls > 10);
    QCOMPARE(last, 1.0);
  }

  void invalidSettings_data() {
    QTest::addColumn<int>("which");
    for (int i = 0; i < 5; ++i) QTest::newRow(qPrintable(QString::number(i))) << i;
  }
  void invalidSettings() {
    QFETCH(int, which);
    AdaptiveControlSettings s;
    switch (which) {
      case 0:
        s.beta = 1.5;
        break;
      case 1:
        s.feed_max_m_s = 0.0;
        break;
      case 2:
        s.force_reference_N = -1.0;
        break;
      case 3:
        s.workpiece.steps.clear();
        break;
      default:
        s.rls.forgetting_factor = 0.0;
        break;
    }
    QVERIFY_THROWS_EXCEPTION(InvalidInput, simulateAdaptiveForceControl(s));
  }
};

MX_REGISTER_TEST(TestClosedLoop)
#include "test_closed_loop.moc"
