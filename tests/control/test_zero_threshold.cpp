// Where a zero of H_beta leaves the unit circle: ours vs the paper's -0.6 and the first-order formula.
#include <cmath>

#include "control/force_plant.h"
#include "control/zero_threshold.h"
#include "core/invalid_input.h"
#include "test_registry.h"

using namespace mx;

class TestZeroThreshold : public QObject {
  Q_OBJECT
 private slots:
  // Our plant (tau_c = half a tooth period = T/8, not calibrated): threshold -0.5720; the paper says -0.6.
  void paperPlant() {
    const CuttingProcess process;
    const double T = spindlePeriod(process);
    const ZeroThresholdResult r = unstableZeroThreshold(makeForcePlant(process, 2e-3).stateSpace(), T);
    QVERIFY(r.found);
    QCOMPARE(static_cast<int>(r.crossings.size()), 1);  // no crossing for beta > 0
    QVERIFY2(std::abs(r.threshold_beta - (-0.571987)) < 1e-5, qPrintable(QString::number(r.threshold_beta, 'g', 10)));
    QVERIFY(std::abs(r.threshold_beta - (-0.6)) < 0.03);  // within 5 % of the paper's value
    // zeros do not depend on the gain (depth)
    const ZeroThresholdResult r5 = unstableZeroThreshold(makeForcePlant(process, 5e-3).stateSpace(), T);
    QVERIFY(std::abs(r5.threshold_beta - r.threshold_beta) < 1e-9);
    // just inside / outside
    QVERIFY(maxZeroModulus(makeForcePlant(process, 2e-3).stateSpace(), T, r.threshold_beta + 1e-6) < 1.0);
    QVERIFY(maxZeroModulus(makeForcePlant(process, 2e-3).stateSpace(), T, r.threshold_beta - 1e-6) > 1.0);
  }

  // With a negligible drive lag the plant is first order: threshold -(1-a)/(2(1-c)), a = e^{-T/tau}, c = tau(1-a)/T.
  void firstOrderFormula_data() {
    QTest::addColumn<double>("T_over_tau");
    QTest::newRow("T/tau = 2") << 2.0;
    QTest::newRow("T/tau = 6 (the paper's -0.6)") << 6.0;
    QTest::newRow("T/tau = 8 (our default)") << 8.0;
    QTest::newRow("T/tau = 30") << 30.0;
  }
  void firstOrderFormula() {
    QFETCH(double, T_over_tau);
    const double T = 0.1, tau = T / T_over_tau;
    ForcePlant p;
    p.gain_N_s_per_m = 50.0;
    p.tau_m_s = 1e-7 * T;  // drive pole e^{-1e7} = 0
    p.tau_c_s = tau;
    const double a = std::exp(-T / tau), c = tau * (1.0 - a) / T;
    const double expected = -(1.0 - a) / (2.0 * (1.0 - c));
    const ZeroThresholdResult r = unstableZeroThreshold(p.stateSpace(), T);
    if (expected < -1.0) {
      QVERIFY(!r.found);
      return;
    }
    QVERIFY(r.found);
    QVERIFY2(std::abs(r.threshold_beta - expected) < 1e-6,
             qPrintable(QString("%1 vs %2").arg(r.threshold_beta, 0, 'g', 10).arg(expected, 0, 'g', 10)));
  }

  void invalid() {
    const StateSpace2 s = makeForcePlant(CuttingProcess{}, 2e-3).stateSpace();
    QVERIFY_THROWS_EXCEPTION(InvalidInput, unstableZeroThreshold(s, 0.1, 0.5, 0.4));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, unstableZeroThreshold(s, 0.1, -2.0, 0.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, unstableZeroThreshold(s, 0.1, -1.0, 1.0, 1));
  }
};

MX_REGISTER_TEST(TestZeroThreshold)
#include "test_zero_threshold.moc"
