// SupervisionMetricsAccumulator: maximum power against the limit, force overshoot over F_ref, the
// TDS chatter indicator (sustained over 10 revolutions) and the supervisor's detector.
#include "supervisor/supervision_metrics.h"
#include "test_registry.h"

using namespace mx;

namespace {
// Binary-exact times: Ts = 1/1024 s, a revolution = 1/32 s = 32 samples, 10 revolutions = 320 samples.
constexpr double kTs = 1.0 / 1024.0;

MetricsSettings settings() {
  MetricsSettings s;
  s.reference_force_N = 200.0;
  s.power_limit_W = 2000.0;
  s.sample_period_s = kTs;
  s.spindle_period_s = 1.0 / 32.0;
  s.chatter_indicator_threshold = 0.02;
  return s;
}

// Samples i = first .. last (t = i Ts) with the given indicator, all applicable.
void indicate(SupervisionMetricsAccumulator& m, int first, int last, double indicator) {
  for (int i = first; i <= last; ++i) m.addChatterIndicator(i * kTs, true, indicator);
}
}  // namespace

class TestSupervisionMetrics : public QObject {
  Q_OBJECT
 private slots:
  void powerAgainstTheLimit() {
    SupervisionMetricsAccumulator m(settings());
    m.addPower(1000.0, false);
    m.addPower(1800.0, false);  // not steady: counts for the maximum only
    m.addPower(1500.0, true);
    m.addPower(1200.0, true);
    QCOMPARE(m.current().max_power_W, 1800.0);
    QCOMPARE(m.current().steady_max_power_pct_of_limit, 75.0);
    QCOMPARE(m.current().max_power_pct_of_limit, 0.0);  // set by finish
    const SupervisionMetrics f = m.finish(12.5, 0.25);
    QCOMPARE(f.max_power_pct_of_limit, 90.0);
    QCOMPARE(f.steady_max_power_pct_of_limit, 75.0);
    QCOMPARE(f.cycle_time_s, 12.5);
    QCOMPARE(f.run_seconds, 0.25);
  }

  // overshoot = 100 (max F_Y - F_ref) / F_ref; below the reference it is negative.
  void overshoot() {
    SupervisionMetricsAccumulator m(settings());
    QCOMPARE(m.current().reference_force_N, 200.0);
    for (double f : {150.0, 230.0, 210.0}) m.addContactForce(0.0, f);
    QCOMPARE(m.finish(1.0, 0.0).max_F_Y_N, 230.0);
    QCOMPARE(m.finish(1.0, 0.0).overshoot_pct, 15.0);

    SupervisionMetricsAccumulator low(settings());
    low.addContactForce(0.0, 150.0);
    QCOMPARE(low.finish(1.0, 0.0).overshoot_pct, -25.0);
  }

  // A restart of the force controller opens a transient: its peak, overshoot and the time until F_Y
  // enters the 2 % band (196..204 N) for 0.4 s; the exit from the part afterwards does not undo it.
  void forceTransients() {
    SupervisionMetricsAccumulator m(settings());
    m.addContactForce(0.0, 500.0);  // before any restart: the overall maximum only
    m.startForceTransient(1.0);
    m.addContactForce(1.0, 150.0);
    m.addContactForce(1.1, 260.0);  // peak: 30 % over 200 N
    m.addContactForce(1.2, 201.0);  // in the band, but leaves it again
    m.addContactForce(1.3, 190.0);
    for (int i = 0; i <= 10; ++i) m.addContactForce(1.5 + 0.05 * i, 203.0);  // 1.5 .. 2.0 s inside
    m.addContactForce(2.1, 40.0);                                            // the tool leaves the part
    m.startForceTransient(3.0);
    m.addContactForce(3.0, 180.0);  // never settles
    const SupervisionMetrics f = m.finish(4.0, 0.0);
    QCOMPARE(f.max_F_Y_N, 500.0);
    QCOMPARE(f.force_transients.size(), std::size_t(2));
    QCOMPARE(f.force_transients[0].t_s, 1.0);
    QCOMPARE(f.force_transients[0].peak_F_Y_N, 260.0);
    QCOMPARE(f.force_transients[0].overshoot_pct, 30.0);
    QCOMPARE(f.force_transients[0].settling_s, 0.5);
    QCOMPARE(f.force_transients[1].overshoot_pct, -10.0);
    QCOMPARE(f.force_transients[1].settling_s, -1.0);
  }

  void passesCounted() {
    SupervisionMetricsAccumulator m(settings());
    m.countPass();
    m.countPass();
    QCOMPARE(m.finish(0.0, 0.0).passes, 2);
  }

  // Chatter needs 10 revolutions (320 samples) above the threshold in a row: samples 1 .. 320 span
  // 319 Ts, not enough; sample 321 makes it sustained from the run's start.
  void tdsChatterSustained() {
    SupervisionMetricsAccumulator m(settings());
    indicate(m, 1, 320, 0.05);
    QVERIFY(!m.finish(1.0, 0.0).chatter_detected);
    QCOMPARE(m.current().tds_chatter_s, 320 * kTs);
    indicate(m, 321, 321, 0.05);
    const SupervisionMetrics f = m.finish(1.0, 0.0);
    QVERIFY(f.chatter_detected);
    QVERIFY(!f.detector_fired);
    QCOMPARE(f.chatter_time_s, kTs);
    QCOMPARE(f.tds_chatter_s, 321 * kTs);
  }

  // A sample below the threshold, or one where the indicator does not apply (tool off the part, feed
  // stopped), restarts the run; the time above the threshold still adds up.
  void tdsRunRestarts() {
    SupervisionMetricsAccumulator m(settings());
    indicate(m, 1, 200, 0.05);
    m.addChatterIndicator(201 * kTs, true, 0.02);  // at the threshold: not above
    indicate(m, 202, 400, 0.05);
    m.addChatterIndicator(401 * kTs, false, 0.05);
    indicate(m, 402, 800, 0.05);
    const SupervisionMetrics f = m.finish(1.0, 0.0);
    QVERIFY(f.chatter_detected);
    QCOMPARE(f.chatter_time_s, 402 * kTs);
    QCOMPARE(f.tds_chatter_s, (200 + 199 + 399) * kTs);
  }

  // The detector's first signal sets the chatter time, and takes precedence over the TDS indicator.
  void detectorFirstSignal() {
    SupervisionMetricsAccumulator m(settings());
    indicate(m, 1, 400, 0.05);
    m.addDetectorSignal(0.5, false);
    m.addDetectorSignal(0.75, true);
    m.addDetectorSignal(0.875, true);
    QVERIFY(m.current().detector_fired);
    QCOMPARE(m.current().chatter_time_s, 0.75);
    const SupervisionMetrics f = m.finish(1.0, 0.0);
    QVERIFY(f.chatter_detected);
    QCOMPARE(f.chatter_time_s, 0.75);
  }

  void noChatter() {
    SupervisionMetricsAccumulator m(settings());
    indicate(m, 1, 1000, 0.01);
    const SupervisionMetrics f = m.finish(1.0, 0.0);
    QVERIFY(!f.chatter_detected);
    QVERIFY(!f.detector_fired);
    QCOMPARE(f.chatter_time_s, -1.0);
    QCOMPARE(f.tds_chatter_s, 0.0);
  }
};

MX_REGISTER_TEST(TestSupervisionMetrics)
#include "test_supervision_metrics.moc"
