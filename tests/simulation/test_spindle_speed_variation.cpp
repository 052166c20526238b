// Spindle speed variation (seed eq. 12): N(t) = N0 (1 + a sin(2 pi f t)), theta(t) integrated
// analytically, the tooth delay tau(t) from theta(t) - theta(t - tau) = 2 pi / n_t (Newton), and the
// general (variable-delay) RK4 kernel, which at a = 0 must reproduce the constant-speed kernel.
#include <cmath>
#include <numbers>

#include "model/cutting_force.h"
#include "simulation/simulation.h"
#include "simulation/spindle_kinematics.h"
#include "simulation/time_domain_simulator.h"
#include "support/fixtures.h"
#include "support/vector_compare.h"
#include "test_registry.h"

using namespace mx;

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;

using mx::test::maxRelativeDifference;
}  // namespace

class TestSpindleSpeedVariation : public QObject {
  Q_OBJECT
 private slots:
  void constantSpeedKinematics() {
    const SpindleKinematics k(100.0, {0.0, 7.0}, 3);
    QVERIFY(k.constantSpeed());
    QCOMPARE(k.speedRevPerS(0.123), 100.0);
    QCOMPARE(k.angleRad(0.5), kTwoPi * 50.0);
    QCOMPARE(k.toothDelayS(0.7), 1.0 / 300.0);
    QCOMPARE(k.maxToothDelayS(), k.pitchRad() / (kTwoPi * 100.0));
    QVERIFY(SpindleKinematics(100.0, {0.2, 0.0}, 3).constantSpeed());  // f = 0: N(t) = N0
  }

  // theta' = 2 pi N(t) (eq. 12), checked by central differences.
  void angleIntegratesSpeed() {
    const SpindleKinematics k(96.0, {0.3, 11.0}, 3);
    for (double t : {0.0, 0.013, 0.4, 2.71}) {
      const double h = 1e-6;
      const double derivative = (k.angleRad(t + h) - k.angleRad(t - h)) / (2 * h);
      QVERIFY(std::abs(derivative / (kTwoPi * k.speedRevPerS(t)) - 1.0) < 1e-8);
      QCOMPARE(k.speedRevPerS(t), 96.0 * (1.0 + 0.3 * std::sin(kTwoPi * 11.0 * t)));
    }
    QCOMPARE(k.angleRad(0.0), 0.0);
  }

  void delayMatchesAngle_data() {
    QTest::addColumn<double>("a");
    QTest::addColumn<double>("f");
    QTest::addColumn<double>("t");
    QTest::addColumn<int>("pitches");
    QTest::newRow("a 0.1, 2 Hz") << 0.1 << 2.0 << 0.3 << 1;
    QTest::newRow("a 0.3, 20 Hz") << 0.3 << 20.0 << 1.234 << 1;
    QTest::newRow("a -0.5, 7 Hz, t < tau (analytic pre-history)") << -0.5 << 7.0 << 0.001 << 1;
    QTest::newRow("a 0.9, 50 Hz, late") << 0.9 << 50.0 << 20.0 << 1;
    QTest::newRow("a 0.2, 5 Hz, third previous tooth") << 0.2 << 5.0 << 0.77 << 3;
    QTest::newRow("a 0.05, 300 Hz (faster than a revolution)") << 0.05 << 300.0 << 0.5 << 1;
  }
  void delayMatchesAngle() {
    QFETCH(double, a);
    QFETCH(double, f);
    QFETCH(double, t);
    QFETCH(int, pitches);
    const SpindleKinematics k(5800.0 / 60.0, {a, f}, 3);
    const double angle = pitches * k.pitchRad();
    const double tau = k.angleDelayS(t, angle, pitches * k.nominalToothPeriodS());
    // theta(t) - theta(t - tau) = k 2 pi / n_t, to 1e-9 (both from the direct angle law).
    QVERIFY2(std::abs(k.angleRad(t) - k.angleRad(t - tau) - angle) < 1e-9 * angle,
             qPrintable(QString("residual %1 rad").arg(k.angleRad(t) - k.angleRad(t - tau) - angle)));
    QVERIFY(tau >= angle / (kTwoPi * k.speedRevPerS(0) * (1 + std::abs(a))) * (1 - 1e-12));
    QVERIFY(tau <= pitches * k.maxToothDelayS() * (1 + 1e-12));
    if (pitches == 1) QCOMPARE(k.toothDelayS(t), tau);
    // A poor initial guess converges to the same root.
    QVERIFY(std::abs(k.angleDelayS(t, angle, 1e3) - tau) < 1e-12 * tau);
  }

  // The general kernel (angles from theta(t), delay by Newton, Hermite history at t - tau) run at a = 0
  // against the constant-speed kernel (tabulated angles, stored samples).
  void zeroAmplitudeReproducesConstantSpeed_data() {
    QTest::addColumn<int>("tool");
    QTest::addColumn<double>("rpm");
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<int>("passes");
    QTest::newRow("R1 5800 rpm, b 0.3 mm") << 1 << 5800.0 << 0.3 << 1;
    QTest::newRow("R1 4000 rpm, b 0.2 mm, K = 3") << 1 << 4000.0 << 0.2 << 3;
    QTest::newRow("Insperger half immersion down, 10000 rpm, b 0.2 mm") << 2 << 10000.0 << 0.2 << 1;
  }
  void zeroAmplitudeReproducesConstantSpeed() {
    QFETCH(int, tool);
    QFETCH(double, rpm);
    QFETCH(double, depth_mm);
    QFETCH(int, passes);
    const MillingSetup setup = tool == 1 ? test::rubioR1() : test::insperger(0.5);
    const OperatingPoint point{rpm / 60.0, depth_mm * 1e-3, 0.1e-3};
    SimulationOptions options;
    options.revolutions = 30;
    options.evaluated_revolutions = 10;
    options.regenerative_passes = passes;
    options.ssv = {0.0, 5.0};
    const SimulationResult constant = simulateMilling(setup, point, options);
    TimeDomainSimulator general(setup, point, options);
    general.run({}, TimeDomainSimulator::Kernel::VariableSpeed);
    const SimulationTrace& trace = general.trace();
    QCOMPARE(trace.size(), constant.trace.size());
    const double dx = maxRelativeDifference(trace.x_m, constant.trace.x_m);
    const double dy = setup.modes_y.empty() ? 0.0 : maxRelativeDifference(trace.y_m, constant.trace.y_m);
    const double df = maxRelativeDifference(trace.force_n, constant.trace.force_n);
    qInfo("general vs constant-speed kernel at a = 0: x %.1e, y %.1e, |F| %.1e", dx, dy, df);
    QVERIFY(dx < 1e-9 && dy < 1e-9 && df < 1e-9);
    QVERIFY(std::abs(general.window().max_force_n / constant.indicators.peak_force_n - 1.0) < 1e-9);
  }

  // The constant-speed kernel refuses a varying speed.
  void constantKernelRequiresConstantSpeed() {
    SimulationOptions options;
    options.ssv = {0.1, 5.0};
    TimeDomainSimulator simulator(test::rubioR1(), {100.0, 1e-4, 1e-4}, options);
    QVERIFY_THROWS_EXCEPTION(std::logic_error, simulator.run({}, TimeDomainSimulator::Kernel::ConstantSpeed));
  }

  // With a > 0 the cut is still stable at q*, the forces stay those of the rigid tool to ~1e-3, and the
  // peak power follows the peak speed: P = pi D N0 (1 + a) sum F_t (Pareto eq. 8).
  void variationRunsAndScalesPower_data() {
    QTest::addColumn<double>("a");
    QTest::addColumn<double>("f");
    QTest::newRow("a 0.1, 5 Hz") << 0.1 << 5.0;
    QTest::newRow("a 0.2, 5 Hz") << 0.2 << 5.0;
    QTest::newRow("a 0.05, 10 Hz") << 0.05 << 10.0;
  }
  void variationRunsAndScalesPower() {
    QFETCH(double, a);
    QFETCH(double, f);
    const MillingSetup setup = test::rubioR1();
    const OperatingPoint q_star{5800.0 / 60.0, 0.4924e-3, 0.2722e-3};
    SimulationOptions options;
    options.ssv = {a, f};  // the 20-revolution window (0.207 s) spans a whole period of 5 or 10 Hz
    const SimulationResult result = simulateMilling(setup, q_star, options);
    const ChatterIndicators& ind = result.indicators;
    QVERIFY(!result.diverged);
    QVERIFY(!ind.chatter);
    QVERIFY(std::abs(ind.eta - 1.0) < 2e-3);
    const CutPerformance rigid = evaluateCut(setup, q_star);
    const double ratio = ind.peak_power_w / rigid.peak_power_w;
    qInfo("peak power %.2f W = %.5f x the constant-speed value", ind.peak_power_w, ratio);
    QVERIFY(std::abs(ratio - (1.0 + a)) < 5e-3);
  }

  // Continuity in a: a tiny variation changes the trajectory by a tiny amount.
  void smallAmplitudeIsContinuous() {
    const MillingSetup setup = test::rubioR1();
    const OperatingPoint point{5800.0 / 60.0, 0.3e-3, 0.1e-3};
    SimulationOptions options;
    options.revolutions = 25;
    options.evaluated_revolutions = 5;
    const SimulationResult base = simulateMilling(setup, point, options);
    options.ssv = {1e-7, 3.0};
    const SimulationResult varied = simulateMilling(setup, point, options);
    const double dx = maxRelativeDifference(varied.trace.x_m, base.trace.x_m);
    QVERIFY2(dx < 1e-4, qPrintable(QString::number(dx)));
  }
};

MX_REGISTER_TEST(TestSpindleSpeedVariation)
#include "test_spindle_speed_variation.moc"
