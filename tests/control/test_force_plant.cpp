// Continuous force plant (eq. 21-23): immersion function, gain K_p, default tau_c, validation.
#include <cmath>

#include "control/force_plant.h"
#include "core/invalid_input.h"
#include "test_registry.h"

using namespace mx;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

class TestForcePlant : public QObject {
  Q_OBJECT
 private slots:
  void immersion_data() {
    QTest::addColumn<double>("start");
    QTest::addColumn<double>("exit");
    QTest::addColumn<int>("teeth");
    QTest::addColumn<double>("expected");
    QTest::newRow("full immersion, 4 teeth") << 0.0 << kPi << 4 << 4.0 / kPi;
    QTest::newRow("half immersion up-milling") << 0.0 << kPi / 2 << 4 << 4.0 / (2.0 * kPi);
    QTest::newRow("half immersion down-milling") << kPi / 2 << kPi << 2 << 2.0 / (2.0 * kPi);
    QTest::newRow("slot, 1 tooth") << 0.0 << kPi << 1 << 1.0 / kPi;
  }
  void immersion() {
    QFETCH(double, start);
    QFETCH(double, exit);
    QFETCH(int, teeth);
    QFETCH(double, expected);
    QVERIFY(std::abs(immersionFunction(start, exit, teeth) - expected) < 1e-15);
  }

  void paperGain() {
    // K_p = K_c b a / (N n_t) = 1200 N/mm^2 * 2 mm * (4/pi) / (715/60 * 4) = 64.107 N/(mm/s)
    const ForcePlant p = makeForcePlant(CuttingProcess{}, 2e-3);
    const double expected = 1200e6 * 2e-3 * (4.0 / kPi) / (715.0 / 60.0 * 4.0);
    QVERIFY(std::abs(p.gain_N_s_per_m - expected) < 1e-9 * expected);
    QVERIFY(std::abs(p.gain_N_s_per_m * 1e-3 - 64.107) < 1e-3);
    // the static force at the 1.2 kN reference needs 18.7 mm/s at 2 mm
    QVERIFY(std::abs(1200.0 / p.gain_N_s_per_m * 1e3 - 18.72) < 0.01);
    QCOMPARE(p.tau_m_s, 1e-4);
    QVERIFY(std::abs(p.tau_c_s - 60.0 / 715.0 / 8.0) < 1e-15);  // half a tooth period
  }

  void explicitTauC() {
    CuttingProcess c;
    c.process_time_constant_s = 0.02;
    QCOMPARE(makeForcePlant(c, 1e-3).tau_c_s, 0.02);
  }

  void invalid_data() {
    QTest::addColumn<int>("which");
    for (int i = 0; i < 6; ++i) QTest::newRow(qPrintable(QString::number(i))) << i;
  }
  void invalid() {
    QFETCH(int, which);
    CuttingProcess c;
    double depth = 1e-3;
    switch (which) {
      case 0:
        c.cutting_pressure_Pa = 0.0;
        break;
      case 1:
        c.spindle_rev_s = -1.0;
        break;
      case 2:
        c.teeth = 0;
        break;
      case 3:
        c.exit_angle_rad = 4.0;
        break;
      case 4:
        c.drive_time_constant_s = std::nan("");
        break;
      default:
        depth = -1.0;
        break;
    }
    QVERIFY_THROWS_EXCEPTION(InvalidInput, makeForcePlant(c, depth));
  }
};

MX_REGISTER_TEST(TestForcePlant)
#include "test_force_plant.moc"
