// Available spindle power P_av(N) = min(P_max, 2 pi N T_max, P_curve(N)) (model/spindle_power.h):
// the torque line, its corner speed with P_max, the curve's interpolation and ends, and the minimum
// when every limit is given. Rubio et al. Pareto paper, Table 4: P = 0.3 pi N W, a 9 N·m torque.
#include <cmath>
#include <limits>
#include <numbers>

#include "core/invalid_input.h"
#include "model/spindle_power.h"
#include "test_registry.h"

using namespace mx;
constexpr double kInf = std::numeric_limits<double>::infinity();

namespace {
double rps(double rpm) {
  return rpm / 60.0;
}
// Rows at 1000, 3000 and 6000 rpm: 2000, 4000 and 3000 W.
SpindlePowerCurve threeRows() {
  SpindlePowerCurve c;
  c.curve = {{rps(1000), 2000.0}, {rps(3000), 4000.0}, {rps(6000), 3000.0}};
  return c;
}
}  // namespace

class TestSpindlePower : public QObject {
  Q_OBJECT
 private slots:
  void noLimitIsInfinite() {
    const SpindlePowerCurve c;
    QVERIFY(std::isinf(c.available(rps(3000))));
    QVERIFY(c.constant());
  }

  void constantPowerAtEverySpeed() {
    SpindlePowerCurve c;
    c.max_power_w = 2745.3;
    QCOMPARE(c.available(rps(100)), 2745.3);
    QCOMPARE(c.available(rps(12000)), 2745.3);
    QVERIFY(c.constant());
  }

  // 9 N·m: P = 2 pi (N/60) 9 = 0.3 pi N W (Table 4: 1696.5 W at 1800 rpm).
  void torqueLine() {
    SpindlePowerCurve c;
    c.max_torque_nm = 9.0;
    QVERIFY(!c.constant());
    QCOMPARE_LE(std::abs(c.available(rps(1800)) - 0.3 * std::numbers::pi * 1800.0), 1e-9);
    QCOMPARE_LE(std::abs(c.available(rps(1800)) - 1696.460), 1e-3);
    QCOMPARE_LE(std::abs(c.available(rps(2412)) - 2273.256), 1e-3);
    QCOMPARE(c.available(0.0), 0.0);
  }

  // Corner (base) speed N_c = P_max / (2 pi T): 2745.3 / (2 pi 9) rev/s = 2912.85 rpm.
  void cornerSpeed() {
    SpindlePowerCurve c;
    c.max_power_w = 2745.3;
    c.max_torque_nm = 9.0;
    const double corner = 2745.3 / (2.0 * std::numbers::pi * 9.0);
    QCOMPARE_LE(std::abs(corner * 60.0 - 2912.854), 0.001);
    QCOMPARE_LE(std::abs(c.available(corner) - 2745.3), 1e-9);
    QCOMPARE_LE(std::abs(c.available(0.9 * corner) - 0.9 * 2745.3), 1e-9);  // torque-limited below
    QCOMPARE(c.available(1.1 * corner), 2745.3);                            // power-limited above
  }

  void curveInterpolation() {
    const SpindlePowerCurve c = threeRows();
    QCOMPARE_LE(std::abs(c.available(rps(2000)) - 3000.0), 1e-9);  // halfway between rows 0 and 1
    QCOMPARE_LE(std::abs(c.available(rps(4500)) - 3500.0), 1e-9);  // halfway between rows 1 and 2
    QCOMPARE_LE(std::abs(c.available(rps(3000)) - 4000.0), 1e-9);  // on a row
    QCOMPARE_LE(std::abs(c.available(rps(500)) - 1000.0), 1e-9);   // below the first row: constant torque
    QCOMPARE(c.available(0.0), 0.0);
    QCOMPARE(c.available(rps(9000)), 3000.0);  // above the last row: its power
  }

  // All three: the minimum. P_max 3600 W, T 9 N·m (0.3 pi N W), the three-row curve.
  void bothGivenTakesTheMinimum() {
    SpindlePowerCurve c = threeRows();
    c.max_power_w = 3600.0;
    c.max_torque_nm = 9.0;
    QCOMPARE_LE(std::abs(c.available(rps(1000)) - 942.478), 1e-3);        // torque (curve 2000 W)
    QCOMPARE_LE(std::abs(c.available(rps(3000)) - 2827.433), 1e-3);       // torque (curve 4000 W)
    QCOMPARE_LE(std::abs(c.available(rps(5000)) - 10000.0 / 3.0), 1e-9);  // curve (torque 4712 W)
    QCOMPARE(c.available(rps(4000)), 3600.0);                             // P_max (curve 3667, torque 3770)
  }

  void validation_data() {
    QTest::addColumn<int>("which");
    QTest::addColumn<QString>("expected");
    QTest::newRow("power zero") << 0 << "spindle power: max_power_w = 0: must be > 0 (+inf: no limit)";
    QTest::newRow("torque negative") << 1 << "spindle power: max_torque_nm = -9: must be > 0 (+inf: no limit)";
    QTest::newRow("one row") << 2 << "spindle power: curve size = 1: must be 0 or >= 2 rows";
    QTest::newRow("speeds not increasing")
        << 3 << "spindle power: curve[2].speed_rev_per_s = 50: must be > the previous row's speed";
    QTest::newRow("negative speed") << 4 << "spindle power: curve[0].speed_rev_per_s = -1: must be finite and >= 0";
    QTest::newRow("power nan") << 5 << "spindle power: curve[1].power_w = nan: must be finite and >= 0";
  }

  void validation() {
    QFETCH(int, which);
    QFETCH(QString, expected);
    SpindlePowerCurve c = threeRows();
    c.validate();  // the base is valid
    switch (which) {
      case 0:
        c.max_power_w = 0.0;
        break;
      case 1:
        c.max_torque_nm = -9.0;
        break;
      case 2:
        c.curve.resize(1);
        break;
      case 3:
        c.curve[2].speed_rev_per_s = 50.0;
        break;
      case 4:
        c.curve[0].speed_rev_per_s = -1.0;
        break;
      case 5:
        c.curve[1].power_w = std::nan("");
        break;
      default:
        QFAIL("unknown row");
    }
    try {
      c.validate();
      QFAIL("validate accepted an invalid spindle power curve");
    } catch (const InvalidInput& e) {
      QCOMPARE(QString::fromUtf8(e.what()), expected);
    }
  }
};

MX_REGISTER_TEST(TestSpindlePower)
#include "test_spindle_power.moc"
