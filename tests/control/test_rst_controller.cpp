// RST law with feed saturation [0, f_max] and anti-windup (saturated past controls in R u).
#include <cmath>

#include "control/rst_controller.h"
#include "core/invalid_input.h"
#include "test_registry.h"

using namespace mx;

class TestRstController : public QObject {
  Q_OBJECT
 private slots:
  void lawWithoutSaturation() {
    // R = z - 0.5, S = 2 z, T = 3 z: u(k) = 3 uc(k) - 2 y(k) + 0.5 u(k-1)
    RstController c(-100.0, 100.0);
    c.setDesign({1.0, -0.5}, {2.0, 0.0}, {3.0, 0.0});
    QCOMPARE(c.step(1.0, 0.0), 3.0);
    QCOMPARE(c.step(1.0, 1.0), 3.0 - 2.0 + 1.5);
    QVERIFY(!c.lastSaturated());
  }

  void limitsHold_data() {
    QTest::addColumn<double>("reference");
    QTest::addColumn<double>("measurement");
    QTest::newRow("huge positive demand") << 1e9 << 0.0;
    QTest::newRow("negative demand") << -1e9 << 0.0;
    QTest::newRow("measurement far above") << 0.0 << 1e12;
    QTest::newRow("non-finite measurement") << 1.0 << std::numeric_limits<double>::quiet_NaN();
  }
  void limitsHold() {
    QFETCH(double, reference);
    QFETCH(double, measurement);
    RstController c(0.0, 30.0);
    c.setDesign({1.0, -1.0}, {0.5, 0.0}, {0.5, 0.0});  // an integrator: the worst case for windup
    for (int k = 0; k < 50; ++k) {
      const double u = c.step(reference, measurement);
      QVERIFY(u >= 0.0 && u <= 30.0);
      QVERIFY(std::isfinite(u));
    }
  }

  // After a long saturation the integrator state has not wound up: the control leaves the limit at the first
  // sample where the error changes sign.
  void antiWindup() {
    RstController c(0.0, 30.0);
    c.setDesign({1.0, -1.0}, {0.5, 0.0}, {0.5, 0.0});  // u(k) = u_sat(k-1) + 0.5 (uc - y)
    for (int k = 0; k < 100; ++k) c.step(100.0, 0.0);  // saturated at 30 for 100 samples
    QCOMPARE(c.lastUnsaturated(), 30.0 + 50.0);        // one step beyond the limit, not 100 x 50
    const double u = c.step(0.0, 10.0);                // error -10: leaves saturation at once
    QCOMPARE(u, 30.0 - 5.0);
    QVERIFY(!c.lastSaturated());
  }

  void holdsWithoutDesign() {
    RstController c(0.0, 30.0);
    QCOMPARE(c.step(1200.0, 0.0), 0.0);  // u_min until a design exists
  }

  void invalid() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput, RstController(1.0, 1.0));
    RstController c(0.0, 1.0);
    QVERIFY_THROWS_EXCEPTION(InvalidInput, c.setDesign({2.0, 1.0}, {1.0}, {1.0}));            // not monic
    QVERIFY_THROWS_EXCEPTION(InvalidInput, c.setDesign({1.0, 1.0}, {1.0, 1.0, 1.0}, {1.0}));  // deg S > deg R
  }
};

MX_REGISTER_TEST(TestRstController)
#include "test_rst_controller.moc"
