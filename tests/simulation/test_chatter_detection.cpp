// Chatter detection (seed eq. 11: eta = max|F_dyn| / max|F_static| >= 1.3; Pareto Rule 15: chip
// thickness ratio >= 1.25), the chatter frequency away from tooth-passing harmonics, and the
// Smith-Tlusty suggestion (Rule 16) at a clearly unstable point.
#include <cmath>
#include <limits>
#include <numbers>

#include "simulation/chatter_detection.h"
#include "simulation/simulation.h"
#include "support/fixtures.h"
#include "test_registry.h"

using namespace mx;

namespace {

// Near one of R1's structural modes (603 Hz on x, 666 Hz on y) within 10 %.
bool nearR1Mode(double f) {
  return std::abs(f / 603.0 - 1.0) < 0.10 || std::abs(f / 666.0 - 1.0) < 0.10;
}

WindowSignals syntheticWindow(double chatter_amplitude) {
  WindowSignals w;
  w.sample_rate_hz = 10000.0;
  const int n = 10000;  // 1 s: 1 Hz bins
  for (int i = 0; i < n; ++i) {
    const double t = i / w.sample_rate_hz;
    const double c = std::sin(2.0 * std::numbers::pi * 650.0 * t);
    w.force_n.push_back(100.0 + 20.0 * std::sin(2.0 * std::numbers::pi * 300.0 * t) + chatter_amplitude * c);
    w.x_m.push_back(1e-6 * std::sin(2.0 * std::numbers::pi * 300.0 * t) + 1e-5 * chatter_amplitude * c);
    w.y_m.push_back(0.5e-5 * chatter_amplitude * std::cos(2.0 * std::numbers::pi * 650.0 * t));
  }
  w.max_force_n = 130.0;
  w.max_static_force_n = 100.0;
  w.max_chip_m = 1.1e-4;
  w.max_static_chip_m = 1e-4;
  w.peak_power_w = 900.0;
  return w;
}

ChatterCriteria criteria300() {
  ChatterCriteria c;
  c.teeth = 3;
  c.nominal_rev_per_s = 100.0;  // f_tp = 300 Hz
  return c;
}

}  // namespace

class TestChatterDetection : public QObject {
  Q_OBJECT
 private slots:
  void unstablePointChatters_data() {
    QTest::addColumn<double>("rpm");
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<int>("passes");
    QTest::newRow("R1 5800 rpm, b 3 mm, eq. 7 (K = 1)") << 5800.0 << 3.0 << 1;
    QTest::newRow("R1 5800 rpm, b 3 mm, surface memory K = 4") << 5800.0 << 3.0 << 4;
    QTest::newRow("R1 9000 rpm, b 2 mm, K = 1") << 9000.0 << 2.0 << 1;
    QTest::newRow("R1 3000 rpm, b 2 mm, K = 4") << 3000.0 << 2.0 << 4;
  }
  void unstablePointChatters() {
    QFETCH(double, rpm);
    QFETCH(double, depth_mm);
    QFETCH(int, passes);
    const MillingSetup setup = test::rubioR1();
    const OperatingPoint point{rpm / 60.0, depth_mm * 1e-3, 0.1e-3};
    SimulationOptions options;
    options.regenerative_passes = passes;
    const SimulationResult result = simulateMilling(setup, point, options);
    const ChatterIndicators& ind = result.indicators;
    qInfo("eta %.3g, chip ratio %.3g, f_c %.2f Hz, A_chatter %.3g N, A_tp %.3g N, diverged %d", ind.eta, ind.chip_ratio,
          ind.chatter_frequency_hz.value_or(-1.0), ind.a_chatter, ind.a_toothpass, result.diverged);
    QVERIFY(ind.chatter);
    QVERIFY(ind.chatter_by_eta);
    QVERIFY(ind.eta >= 1.3);
    QVERIFY(ind.chatter_by_chip_ratio);
    QVERIFY(std::isfinite(ind.eta) && std::isfinite(ind.peak_force_n) && std::isfinite(ind.a_chatter));
    QVERIFY(ind.chatter_frequency_hz.has_value());
    const double fc = *ind.chatter_frequency_hz;
    QVERIFY2(nearR1Mode(fc), qPrintable(QString("f_c = %1 Hz").arg(fc)));
    QCOMPARE(ind.tooth_passing_hz, setup.teeth * point.spindle_rev_per_s);
    const int h = static_cast<int>(std::lround(fc / ind.tooth_passing_hz));
    QVERIFY(std::abs(fc - h * ind.tooth_passing_hz) > 0.03 * ind.tooth_passing_hz);  // not a tooth-passing harmonic
    QVERIFY(ind.a_chatter > 0.0);
    // Surface memory bounds the amplitude; eq. 7 alone grows until the divergence limit (D/2).
    if (passes > 1) QVERIFY(!result.diverged && result.simulated_revolutions == options.revolutions);

    // Rule 16: suggested speed with N n_t k = f_c, nearest the current speed.
    const auto choice =
        smithTlustyChoice(fc, setup.teeth, point.spindle_rev_per_s, 0.0, std::numeric_limits<double>::infinity());
    QVERIFY(choice);
    QVERIFY(choice->k >= 1);
    QVERIFY(std::abs(choice->rev_per_s * setup.teeth * choice->k - fc) < 1e-9 * fc);
    const double next_slower = fc / (setup.teeth * (choice->k + 1));
    QVERIFY(std::abs(choice->rev_per_s - point.spindle_rev_per_s) <= std::abs(next_slower - point.spindle_rev_per_s));
    QCOMPARE(*smithTlustySpeed(fc, setup.teeth, point.spindle_rev_per_s, 0.0, std::numeric_limits<double>::infinity()),
             choice->rev_per_s);
  }

  void stablePointDoesNotChatter() {
    const MillingSetup setup = test::rubioR1();
    const OperatingPoint q_star{5800.0 / 60.0, 0.4924e-3, 0.2722e-3};
    const SimulationResult result = simulateMilling(setup, q_star, {});
    const ChatterIndicators& ind = result.indicators;
    QVERIFY(!ind.chatter && !ind.chatter_by_eta && !ind.chatter_by_chip_ratio);
    QVERIFY(!ind.chatter_frequency_hz.has_value());
    // Steady state of a stable cut: the vibration repeats every tooth period, so h = h_static (eq. 7).
    QVERIFY(std::abs(ind.eta - 1.0) < 1e-6);
    QVERIFY(std::abs(ind.chip_ratio - 1.0) < 1e-6);
    QVERIFY(ind.a_toothpass > 1.0);
    QVERIFY(ind.a_chatter < 1e-6 * ind.a_toothpass);
  }

  void syntheticSpectrum() {
    const ChatterIndicators ind = detectChatter(syntheticWindow(5.0), criteria300());
    QCOMPARE(ind.tooth_passing_hz, 300.0);
    QVERIFY(std::abs(ind.a_toothpass - 20.0) < 1e-6);
    QVERIFY(ind.chatter);
    QVERIFY(ind.chatter_frequency_hz);
    QVERIFY(std::abs(*ind.chatter_frequency_hz - 650.0) < 1e-3);
    QVERIFY(std::abs(ind.a_chatter - 5.0) < 1e-6);
    QCOMPARE(ind.peak_force_n, 130.0);
    QCOMPARE(ind.peak_power_w, 900.0);
  }

  void thresholds_data() {
    QTest::addColumn<double>("max_force");
    QTest::addColumn<double>("max_chip");
    QTest::addColumn<bool>("by_eta");
    QTest::addColumn<bool>("by_chip");
    QTest::newRow("both below") << 129.99 << 1.2499e-4 << false << false;
    QTest::newRow("eta exactly 1.3") << 130.0 << 1.0e-4 << true << false;
    QTest::newRow("chip ratio exactly 1.25") << 100.0 << 1.25e-4 << false << true;
    QTest::newRow("both above") << 200.0 << 3e-4 << true << true;
  }
  void thresholds() {
    QFETCH(double, max_force);
    QFETCH(double, max_chip);
    QFETCH(bool, by_eta);
    QFETCH(bool, by_chip);
    WindowSignals w = syntheticWindow(0.0);
    w.max_force_n = max_force;
    w.max_chip_m = max_chip;
    const ChatterIndicators ind = detectChatter(w, criteria300());
    QCOMPARE(ind.eta, max_force / 100.0);
    QCOMPARE(ind.chip_ratio, max_chip / 1e-4);
    QCOMPARE(ind.chatter_by_eta, by_eta);
    QCOMPARE(ind.chatter_by_chip_ratio, by_chip);
    QCOMPARE(ind.chatter, by_eta || by_chip);
    QCOMPARE(ind.chatter_frequency_hz.has_value(), ind.chatter);  // reported only with chatter
  }

  void zeroStaticForceMeansNoAmplification() {
    WindowSignals w = syntheticWindow(0.0);
    w.max_force_n = 0.0;
    w.max_static_force_n = 0.0;
    const ChatterIndicators ind = detectChatter(w, criteria300());
    QCOMPARE(ind.eta, 1.0);
    QVERIFY(!ind.chatter_by_eta);
  }

  void harmonicBands() {
    QCOMPARE(harmonicBandHz(2, 300.0, 1.0, {}), 3.0);                        // 3 bins = 1 % of f_tp
    QCOMPARE(harmonicBandHz(2, 300.0, 0.1, {}), 3.0);                        // 1 % of f_tp
    QCOMPARE(harmonicBandHz(2, 300.0, 40.0, {}), 75.0);                      // capped at f_tp / 4
    QCOMPARE(harmonicBandHz(2, 300.0, 1.0, {0.1, 5.0}), 3.0 + 60.0 + 10.0);  // SSV swing
    QCOMPARE(harmonicBandHz(2, 300.0, 1.0, {0.1, 0.0}), 3.0);                // f = 0: no modulation
  }

  // Variable pitch or runout: the cut repeats once a revolution, so a spindle harmonic (500 Hz = 5 N,
  // not a tooth-passing multiple) is forced vibration; the chatter is the 650 Hz peak between them.
  void spindleHarmonicsForcedForUnequalTeeth() {
    WindowSignals w = syntheticWindow(1.0);
    for (std::size_t i = 0; i < w.x_m.size(); ++i)
      w.x_m[i] += 3e-5 * std::sin(2.0 * std::numbers::pi * 500.0 * static_cast<double>(i) / w.sample_rate_hz);
    ChatterCriteria c = criteria300();
    QVERIFY(std::abs(detectChatter(w, c).largest_nonharmonic_hz - 500.0) < 1e-3);
    c.forced_at_spindle_harmonics = true;
    const ChatterIndicators ind = detectChatter(w, c);
    QVERIFY(std::abs(ind.largest_nonharmonic_hz - 650.0) < 1e-3);
    QCOMPARE(ind.tooth_passing_hz, 300.0);
    QCOMPARE(harmonicBandHz(5, 100.0, 1.0, {}), 3.0);  // 3 bins around 5 N
  }
};

MX_REGISTER_TEST(TestChatterDetection)
#include "test_chatter_detection.moc"
