// TimeDomainSimulator: the fixed-step RK4 kernel (seed section 2E) - step size rule, trace recording,
// steady-state forces against the static model, surface memory and the divergence stop.
#include <cmath>
#include <numbers>

#include "model/cutting_force.h"
#include "simulation/time_domain_simulator.h"
#include "support/fixtures.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::kRubioQStar;

double maxAbs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}
}  // namespace

class TestTimeDomainSimulator : public QObject {
  Q_OBJECT
 private slots:
  // m = max(32, ceil(40 f_max T)): >= 40 steps per period of the highest mode, >= 32 per tooth period.
  void automaticStepCount_data() {
    QTest::addColumn<int>("tool");
    QTest::addColumn<double>("rpm");
    QTest::addColumn<int>("steps");
    QTest::newRow("R1 5800 rpm: 40 * 666 Hz * 3.448 ms = 91.9") << 1 << 5800.0 << 92;
    QTest::newRow("R1 60000 rpm: minimum 32") << 1 << 60000.0 << 32;
    QTest::newRow("R2 20000 rpm: 40 * 911.65 Hz * 1.5 ms = 54.7") << 2 << 20000.0 << 55;
    QTest::newRow("rigid tool: minimum 32") << 3 << 5800.0 << 32;
  }
  void automaticStepCount() {
    QFETCH(int, tool);
    QFETCH(double, rpm);
    QFETCH(int, steps);
    MillingSetup s = tool == 2 ? test::rubioR2() : test::rubioR1();
    if (tool == 3) s.modes_x.clear(), s.modes_y.clear();
    QCOMPARE(automaticStepsPerToothPeriod(s, rpm / 60.0), steps);
    SimulationOptions options;
    const TimeDomainSimulator sim(s, {rpm / 60.0, 1e-4, 1e-4}, options);
    QCOMPARE(sim.stepsPerToothPeriod(), steps);
    QCOMPARE(sim.dt(), 60.0 / rpm / s.teeth / steps);
    QCOMPARE(sim.totalSteps(), std::int64_t{60} * s.teeth * steps);
    options.steps_per_tooth_period = 50;
    QCOMPARE(TimeDomainSimulator(s, {rpm / 60.0, 1e-4, 1e-4}, options).stepsPerToothPeriod(), 50);
  }

  void recordEveryDecimates() {
    SimulationOptions options;
    options.revolutions = 4;
    options.evaluated_revolutions = 1;
    TimeDomainSimulator full(test::rubioR1(), kRubioQStar, options);
    full.run();
    options.record_every = 7;
    TimeDomainSimulator decimated(test::rubioR1(), kRubioQStar, options);
    decimated.run();
    const SimulationTrace& a = full.trace();
    const SimulationTrace& b = decimated.trace();
    QCOMPARE(a.size(), static_cast<std::size_t>(full.totalSteps()));
    QCOMPARE(b.size(), static_cast<std::size_t>((full.totalSteps() + 6) / 7));
    for (std::size_t k = 0; k < b.size(); ++k) {
      QCOMPARE(b.time_s[k], a.time_s[7 * k]);
      QCOMPARE(b.time_s[k], 7.0 * k * full.dt());
      QCOMPARE(b.x_m[k], a.x_m[7 * k]);
      QCOMPARE(b.power_w[k], a.power_w[7 * k]);
    }
    // Decimation does not touch the indicator inputs.
    QCOMPARE(decimated.window().max_force_n, full.window().max_force_n);
    QCOMPARE(decimated.window().force_n.size(), static_cast<std::size_t>(full.totalSteps() / 4));
  }

  // In the steady state of a stable cut the vibration repeats every tooth period, so eq. 7 gives the
  // static chip and the simulated force equals the static force of mx::staticForce at every sample.
  void steadyStateForceIsStatic_data() {
    QTest::addColumn<int>("tool");
    QTest::newRow("R1 full immersion up-milling at q*") << 1;
    QTest::newRow("Insperger 30 % immersion down-milling") << 2;
  }
  void steadyStateForceIsStatic() {
    QFETCH(int, tool);
    const MillingSetup s = tool == 1 ? test::rubioR1() : test::insperger(0.3);
    const OperatingPoint p = tool == 1 ? kRubioQStar : OperatingPoint{10000.0 / 60.0, 0.2e-3, 0.1e-3};
    TimeDomainSimulator sim(s, p, {});
    sim.run();
    const SimulationTrace& tr = sim.trace();
    const std::size_t last_rev =
        static_cast<std::size_t>(sim.stepsPerToothPeriod()) * static_cast<std::size_t>(s.teeth);
    double worst = 0.0, peak = 0.0;
    for (std::size_t k = tr.size() - last_rev; k < tr.size(); ++k) {
      // Right-hand limit at t_k, as recorded: a tooth entering exactly at t_k cuts.
      const double theta = 2.0 * std::numbers::pi * p.spindle_rev_per_s * tr.time_s[k] + 1e-9;
      const StaticForce f = staticForce(s, p, theta);
      worst = std::max({worst, std::abs(f.fx_n - tr.fx_n[k]), std::abs(f.fy_n - tr.fy_n[k])});
      peak = std::max(peak, f.resultant());
      QVERIFY(std::abs(tr.power_w[k] - std::numbers::pi * s.diameter_m * p.spindle_rev_per_s * f.tangential_sum_n) <
              1e-3);  // W
    }
    QVERIFY2(worst < 1e-6 * peak, qPrintable(QString("%1 N of %2 N").arg(worst).arg(peak)));
    QVERIFY(maxAbs(tr.x_m) > 1e-7);  // the tool does vibrate (forced), yet the chip is static
  }

  // With K > 1 remembered passes the chip is eq. 7 whenever the previous pass cut, so at a stable
  // point the steady state is the same.
  void surfaceMemoryAgreesWhileCutting() {
    SimulationOptions options;
    TimeDomainSimulator one(test::rubioR1(), kRubioQStar, options);
    one.run();
    options.regenerative_passes = 5;
    TimeDomainSimulator five(test::rubioR1(), kRubioQStar, options);
    five.run();
    QVERIFY(std::abs(five.window().max_force_n / one.window().max_force_n - 1.0) < 1e-9);
    QVERIFY(std::abs(five.trace().x_m.back() / one.trace().x_m.back() - 1.0) < 1e-6);
  }

  // Eq. 7 alone is linear where the teeth cut and grows without bound beyond the stability limit: the
  // run stops at the divergence limit and is evaluated over the revolutions it completed.
  void divergenceStops_data() {
    QTest::addColumn<double>("limit");
    QTest::newRow("automatic limit D/2") << 0.0;
    QTest::newRow("1 mm") << 1e-3;
  }
  void divergenceStops() {
    QFETCH(double, limit);
    SimulationOptions options;
    options.divergence_limit_m = limit;
    const MillingSetup s = test::rubioR1();
    TimeDomainSimulator sim(s, {5800.0 / 60.0, 3e-3, 1e-4}, options);
    sim.run();
    QVERIFY(sim.diverged());
    QVERIFY(sim.simulatedRevolutions() < options.revolutions);
    const double bound = limit > 0.0 ? limit : 0.5 * s.diameter_m;
    QVERIFY(maxAbs(sim.trace().x_m) <= bound && maxAbs(sim.trace().y_m) <= bound);
    QVERIFY(std::isfinite(sim.window().max_force_n) && sim.window().max_force_n > 0.0);
    QVERIFY(sim.window().force_n.size() <= static_cast<std::size_t>(sim.stepsPerToothPeriod() * s.teeth * 20));
    QVERIFY(!sim.window().force_n.empty());
  }

  void rigidToolHasNoVibration() {
    MillingSetup s = test::rubioR1();
    s.modes_x.clear();
    s.modes_y.clear();
    TimeDomainSimulator sim(s, kRubioQStar, {});
    sim.run();
    QVERIFY(sim.finalState().empty());
    QCOMPARE(maxAbs(sim.trace().x_m), 0.0);
    QCOMPARE(sim.window().max_force_n, sim.window().max_static_force_n);
    QVERIFY(!sim.diverged());
  }
};

MX_REGISTER_TEST(TestTimeDomainSimulator)
#include "test_time_domain_simulator.moc"
