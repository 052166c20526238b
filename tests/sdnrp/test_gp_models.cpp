// The GP models K1-K5 of Cus & Zuperl (2008) as printed (reference values computed independently).
#include <cmath>

#include "core/invalid_input.h"
#include "sdnrp/gp_models.h"
#include "test_registry.h"

using namespace mx;

class TestGpModels : public QObject {
  Q_OBJECT
 private slots:
  void printedFormulas() {
    QVERIFY(std::abs(SdnrpModels::desiredForce(0.81) - 187.990285789) < 1e-8);
    QVERIFY(std::abs(SdnrpModels::feedCommand(188.0) - 541.759348121) < 1e-8);
    QVERIFY(std::abs(SdnrpModels::speedCommand(188.0) - 3861.908963194) < 1e-8);
    QVERIFY(std::abs(SdnrpModels::cuttingForce(2134.0, 324.6) - 210.614406670) < 1e-8);
    QVERIFY(std::abs(SdnrpModels::roughness(177.7) - 0.671868822913) < 1e-11);
  }
  void k1AndK5AreInverses() {
    for (double ra = 0.25; ra <= 2.5; ra += 0.05)
      QVERIFY(std::abs(SdnrpModels::roughness(SdnrpModels::desiredForce(ra)) / ra - 1.0) <
              1e-4);  // 0.0254 * 39.37 = 0.999998
  }
  void k2NegativeBelow177N() {
    QVERIFY(SdnrpModels::feedCommand(177.0) < 0.0);
    QVERIFY(SdnrpModels::feedCommand(177.1) > 0.0);
    QVERIFY(SdnrpModels::feedCommand(161.4) < -900.0);  // Table 2, row 1's F_d
  }
  void k4NotMonotonicInFeed() {
    const double f0 = SdnrpModels::turningFeed();
    QVERIFY(std::abs(f0 - 69.6997) < 1e-3);
    const double n = 2000.0;
    QVERIFY(SdnrpModels::cuttingForce(n, 40.0) > SdnrpModels::cuttingForce(n, f0));   // falls below f0
    QVERIFY(SdnrpModels::cuttingForce(n, 400.0) > SdnrpModels::cuttingForce(n, f0));  // rises above f0
    QVERIFY(std::abs(SdnrpModels::cuttingForceFeedSensitivity(f0)) < 1e-12);
    // the sensitivity is the derivative
    const double h = 1e-4, f = 350.0;
    const double fd = (SdnrpModels::cuttingForce(n, f + h) - SdnrpModels::cuttingForce(n, f - h)) / (2 * h);
    QVERIFY(std::abs(SdnrpModels::cuttingForceFeedSensitivity(f) - fd) < 1e-7);
  }
  void domains() {
    QVERIFY_THROWS_EXCEPTION(InvalidInput, SdnrpModels::desiredForce(0.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, SdnrpModels::feedCommand(0.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, SdnrpModels::speedCommand(236.3));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, SdnrpModels::cuttingForce(2000.0, 0.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, SdnrpModels::roughness(293.0));
  }
};

MX_REGISTER_TEST(TestGpModels)
#include "test_gp_models.moc"
