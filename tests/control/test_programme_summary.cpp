// The per-point summary of a programmed run (Pareto paper, Fig. 6) on hand-made series: the windows between the
// step changes, the time-averaged and peak force, the settled values over the last quarter of each point's
// samples, and the analytic feed F_r / K_p(N, b).
#include <cmath>

#include "control/programme_summary.h"
#include "test_registry.h"

using namespace mx;

class TestProgrammeSummary : public QObject {
  Q_OBJECT
 private slots:
  void windowsAndSettledValues() {
    AdaptiveControlSettings s;
    s.force_reference_N = 100.0;
    s.workpiece.steps = {{1e-3, 1e-3, 10.0}, {1e-3, 2e-3, 20.0}};
    ClosedLoopResult r;
    // samples every 0.1 s over [0, 2]; the feed is 1 mm/s up to t = 1 (the change), 3 mm/s after
    for (int k = 0; k <= 20; ++k) {
      ClosedLoopSample smp;
      smp.t = 0.1 * k;
      smp.sampling_period_s = k < 20 ? 0.1 : 0.0;
      smp.feed_m_s = (smp.t < 1.0 - 1e-12 ? 1.0 : 3.0) * 1e-3;
      smp.force_N = smp.t < 1.0 - 1e-12 ? 90.0 : 110.0;
      r.samples.push_back(smp);
    }
    // continuous force: 100 N with a 150 N point at t = 0.5, and 120 N after the change
    for (int i = 0; i <= 40; ++i) {
      ClosedLoopDensePoint p;
      p.t = 0.05 * i;
      p.force_N = i == 10 ? 150.0 : (i <= 20 ? 100.0 : 120.0);
      r.dense.push_back(p);
    }
    r.depth_change_times_s = {1.0};
    const std::vector<ProgrammeSegmentSummary> seg = programmeSegmentSummaries(r, s);
    QCOMPARE(seg.size(), std::size_t{2});
    QCOMPARE(seg[0].start_s, 0.0);
    QCOMPARE(seg[0].end_s, 1.0);
    QCOMPARE(seg[1].end_s, 2.0);
    QCOMPARE(seg[0].samples, 10);
    QCOMPARE(seg[1].samples, 10);  // the final, measurement-only sample is left out
    QCOMPARE(seg[0].peak_force_N, 150.0);
    QVERIFY(std::abs(seg[0].overshoot_pct - 50.0) < 1e-12);
    // trapezoid: 100 N over 1 s plus the 50 N triangle of base 0.1 s
    QVERIFY(std::abs(seg[0].mean_force_N - 102.5) < 1e-9);
    QVERIFY(std::abs(seg[1].mean_force_N - 119.5) < 1e-9);  // the ramp 100 -> 120 over the first 0.05 s
    QVERIFY(std::abs(seg[0].settled_feed_m_s - 1e-3) < 1e-15);
    QVERIFY(std::abs(seg[1].settled_feed_m_s - 3e-3) < 1e-15);
    QCOMPARE(seg[1].settled_force_N, 110.0);
    QCOMPARE(seg[1].spindle_rev_s, 20.0);
    // F_r / K_p with K_p = K_c b a / (N n_t), a = n_t / pi (full immersion)
    const double kp = s.process.cutting_pressure_Pa * 2e-3 / (M_PI * 20.0);
    QVERIFY(std::abs(seg[1].analytic_feed_m_s - 100.0 / kp) < 1e-12 * 100.0 / kp);
  }

  void stepsNotReachedAreLeftOut() {
    AdaptiveControlSettings s;
    s.workpiece.steps = {{1e-3, 1e-3, 0.0}, {1e-3, 2e-3, 0.0}};
    ClosedLoopResult r;
    r.samples.resize(2);
    r.samples[1].t = 1.0;
    r.dense.resize(2);
    r.dense[1].t = 1.0;
    QCOMPARE(programmeSegmentSummaries(r, s).size(), std::size_t{1});
    QVERIFY(programmeSegmentSummaries(ClosedLoopResult{}, s).empty());
  }
};

MX_REGISTER_TEST(TestProgrammeSummary)
#include "test_programme_summary.moc"
