// Modal receptance (sum of modes) and its analytic landmarks.
#include <cmath>
#include <numbers>

#include "model/modal_model.h"
#include "test_registry.h"

using namespace mx;

class TestModalModel : public QObject {
  Q_OBJECT
 private slots:
  void staticAndResonantValues_data() {
    QTest::addColumn<double>("f");
    QTest::addColumn<double>("zeta");
    QTest::addColumn<double>("k");
    QTest::newRow("R1 x") << 603.0 << 0.039 << 5.59e6;
    QTest::newRow("Insperger") << 922.0 << 0.011 << 1.34005e6;
    QTest::newRow("stiff") << 3000.0 << 0.2 << 1e9;
  }
  void staticAndResonantValues() {
    QFETCH(double, f);
    QFETCH(double, zeta);
    QFETCH(double, k);
    const ModalAxis axis{{f, zeta, k}};
    const double w = 2 * std::numbers::pi * f;
    QCOMPARE_LE(std::abs(receptance(axis, {0.0, 0.0}).real() * k - 1.0), 1e-12);          // G(0) = 1/k
    QCOMPARE_LE(std::abs(receptance(axis, {0.0, w}).imag() * 2 * zeta * k + 1.0), 1e-9);  // -1/(2 zeta k)
    // min Re G = -1/(4 k zeta (1+zeta)) at w sqrt(1 + 2 zeta).
    const double re_min = receptance(axis, {0.0, w * std::sqrt(1 + 2 * zeta)}).real();
    QCOMPARE_LE(std::abs(re_min * 4 * k * zeta * (1 + zeta) + 1.0), 1e-9);
    QCOMPARE_LE(std::abs(axis.front().decayRate() - zeta * w), 1e-9);
    QCOMPARE_LE(std::abs(axis.front().modalMass() - k / (w * w)), 1e-12);
  }

  void modesSuperpose() {
    const ModalAxis a{{500, 0.02, 1e7}}, b{{1500, 0.03, 4e7}}, ab{{500, 0.02, 1e7}, {1500, 0.03, 4e7}};
    const std::complex<double> s{-3.0, 2 * std::numbers::pi * 800};
    QCOMPARE_LE(std::abs(receptance(ab, s) - receptance(a, s) - receptance(b, s)), 1e-18);
    QCOMPARE(receptance({}, s), std::complex<double>(0.0, 0.0));  // rigid axis
    QVERIFY(std::isinf(smallestDecayRate({}, {})));
  }
};

MX_REGISTER_TEST(TestModalModel)
#include "test_modal_model.moc"
