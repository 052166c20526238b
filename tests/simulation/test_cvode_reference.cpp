// Cross-check of the fixed-step RK4 simulation (seed section 2E) against an independent CVODE
// integration of the same model (eq. 1-7): trajectories agree to 1 % of the signal's peak over 20
// revolutions at stable cutting points.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/invalid_input.h"
#include "model/cutting_force.h"
#include "simulation/simulation.h"
#include "support/fixtures.h"
#include "test_registry.h"

using namespace mx;

namespace {

// max_k |a_k - b_k| / max_k |b_k| over the first n samples.
double relativeError(const std::vector<double>& a, const std::vector<double>& b, std::size_t n) {
  double diff = 0.0, peak = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    diff = std::max(diff, std::abs(a[k] - b[k]));
    peak = std::max(peak, std::abs(b[k]));
  }
  return diff / peak;
}

MillingSetup twoModesPerAxis() {
  MillingSetup s = test::rubioR1();
  s.modes_x.push_back({1450.0, 0.02, 2.0e7});
  s.modes_y.push_back({1720.0, 0.025, 2.5e7});
  return s;
}

}  // namespace

class TestCvodeReference : public QObject {
  Q_OBJECT
 private slots:
  void agreesWithRk4_data() {
    QTest::addColumn<int>("tool");
    QTest::addColumn<double>("rpm");
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<double>("feed_mm");
    QTest::addColumn<int>("passes");
    QTest::newRow("R1 5800 rpm, b 0.3 mm, 0.1 mm/tooth") << 1 << 5800.0 << 0.3 << 0.1 << 1;
    QTest::newRow("R1 q* (5800 rpm, 0.4924 mm, 0.2722 mm/tooth)") << 1 << 5800.0 << 0.4924 << 0.2722 << 1;
    QTest::newRow("R1 4000 rpm, b 0.2 mm, surface memory K = 3") << 1 << 4000.0 << 0.2 << 0.1 << 3;
    QTest::newRow("R1 + 2nd modes, 7000 rpm, b 0.15 mm") << 2 << 7000.0 << 0.15 << 0.1 << 1;
    QTest::newRow("Insperger, half immersion down-milling, 10000 rpm, b 0.2 mm") << 3 << 10000.0 << 0.2 << 0.1 << 1;
  }
  void agreesWithRk4() {
    QFETCH(int, tool);
    QFETCH(double, rpm);
    QFETCH(double, depth_mm);
    QFETCH(double, feed_mm);
    QFETCH(int, passes);
    const MillingSetup setup = tool == 1 ? test::rubioR1() : tool == 2 ? twoModesPerAxis() : test::insperger(0.5);
    const OperatingPoint point{rpm / 60.0, depth_mm * 1e-3, feed_mm * 1e-3};
    const int revolutions = 20;

    SimulationOptions options;
    options.revolutions = revolutions + 1;
    options.evaluated_revolutions = 1;
    options.regenerative_passes = passes;
    const SimulationResult rk4 = simulateMilling(setup, point, options);
    const SimulationTrace cvode =
        simulateMillingCvode(setup, point, revolutions, 1e-9, rk4.steps_per_tooth_period, passes);

    const std::size_t n = static_cast<std::size_t>(revolutions) * setup.teeth * rk4.steps_per_tooth_period;
    QCOMPARE(cvode.size(), n);
    QVERIFY(rk4.trace.size() > n);
    for (std::size_t k = 0; k < n; k += n / 7) QCOMPARE(cvode.time_s[k], rk4.trace.time_s[k]);
    const double ex = relativeError(rk4.trace.x_m, cvode.x_m, n);
    const double ey = setup.modes_y.empty() ? 0.0 : relativeError(rk4.trace.y_m, cvode.y_m, n);
    const double ef = relativeError(rk4.trace.force_n, cvode.force_n, n);
    qInfo("m = %d: RK4 vs CVODE max error / peak: x %.2e, y %.2e, |F| %.2e", rk4.steps_per_tooth_period, ex, ey, ef);
    QVERIFY2(ex < 0.01, qPrintable(QString("x differs by %1 of its peak").arg(ex)));
    QVERIFY2(ey < 0.01, qPrintable(QString("y differs by %1 of its peak").arg(ey)));
    QVERIFY2(ef < 0.01, qPrintable(QString("|F| differs by %1 of its peak").arg(ef)));
  }

  // Tightening the tolerance moves CVODE's answer by far less than the RK4-CVODE difference bound.
  void toleranceConverges() {
    const MillingSetup setup = test::rubioR1();
    const OperatingPoint point{5800.0 / 60.0, 0.3e-3, 0.1e-3};
    const SimulationTrace loose = simulateMillingCvode(setup, point, 5, 1e-6);
    const SimulationTrace tight = simulateMillingCvode(setup, point, 5, 1e-10);
    QCOMPARE(loose.size(), tight.size());
    QVERIFY(relativeError(loose.x_m, tight.x_m, tight.size()) < 1e-3);
    QVERIFY(relativeError(loose.force_n, tight.force_n, tight.size()) < 1e-3);
  }

  void rigidToolGivesStaticForces() {
    MillingSetup setup = test::rubioR1();
    setup.modes_x.clear();
    setup.modes_y.clear();
    const OperatingPoint point{5800.0 / 60.0, 0.4924e-3, 0.2722e-3};
    const SimulationTrace trace = simulateMillingCvode(setup, point, 1, 1e-8, 40);
    QCOMPARE(trace.size(), std::size_t{120});
    const double h = point.toothPeriodS(setup.teeth) / 40;
    for (std::size_t k = 0; k < trace.size(); ++k) {
      // The trace holds right-hand limits: forces at t_k + 1e-9 h.
      const double theta = 2.0 * std::numbers::pi * point.spindle_rev_per_s * (trace.time_s[k] + 1e-9 * h);
      QCOMPARE(trace.force_n[k], staticForce(setup, point, theta).resultant());
      QCOMPARE(trace.x_m[k], 0.0);
    }
  }

  void rejectsInvalidInput_data() {
    QTest::addColumn<double>("rev_per_s");
    QTest::addColumn<double>("depth");
    QTest::addColumn<double>("feed");
    QTest::addColumn<int>("revolutions");
    QTest::addColumn<double>("rtol");
    QTest::addColumn<QString>("quantity");
    QTest::newRow("zero speed") << 0.0 << 1e-4 << 1e-4 << 2 << 1e-8 << "spindle speed";
    QTest::newRow("negative depth") << 100.0 << -1e-4 << 1e-4 << 2 << 1e-8 << "axial depth";
    QTest::newRow("zero feed") << 100.0 << 1e-4 << 0.0 << 2 << 1e-8 << "feed per tooth";
    QTest::newRow("zero revolutions") << 100.0 << 1e-4 << 1e-4 << 0 << 1e-8 << "revolutions";
    QTest::newRow("rtol too loose") << 100.0 << 1e-4 << 1e-4 << 2 << 0.5 << "relative tolerance";
    QTest::newRow("rtol zero") << 100.0 << 1e-4 << 1e-4 << 2 << 0.0 << "relative tolerance";
  }
  void rejectsInvalidInput() {
    QFETCH(double, rev_per_s);
    QFETCH(double, depth);
    QFETCH(double, feed);
    QFETCH(int, revolutions);
    QFETCH(double, rtol);
    QFETCH(QString, quantity);
    try {
      simulateMillingCvode(test::rubioR1(), {rev_per_s, depth, feed}, revolutions, rtol);
      QFAIL("no InvalidInput thrown");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString(e.what()).contains(quantity), e.what());
    }
  }
};

MX_REGISTER_TEST(TestCvodeReference)
#include "test_cvode_reference.moc"
