// Pole and residue of one mode and the residue -> modal stiffness formula (modal_pole.h).
#include <cmath>
#include <numbers>

#include "modal_fit/modal_pole.h"
#include "test_registry.h"

using namespace mx;

class TestModalPole : public QObject {
  Q_OBJECT
 private slots:
  void roundTrip_data() {
    QTest::addColumn<double>("f");
    QTest::addColumn<double>("zeta");
    QTest::addColumn<double>("k");
    QTest::newRow("light") << 603.0 << 0.001 << 5.59e6;
    QTest::newRow("typical") << 922.0 << 0.02 << 1.34e6;
    QTest::newRow("heavy") << 3000.0 << 0.25 << 1e9;
  }
  void roundTrip() {
    QFETCH(double, f);
    QFETCH(double, zeta);
    QFETCH(double, k);
    const Mode mode{f, zeta, k};
    const auto lambda = poleOf(mode);
    QCOMPARE_LE(std::abs(poleFrequencyHz(lambda) / f - 1.0), 1e-13);
    QCOMPARE_LE(std::abs(poleDampingRatio(lambda) / zeta - 1.0), 1e-12);
    // A = -i w^2 / (2 k w_d): the partial fractions reproduce mx::receptance at any s.
    const auto a = residueOf(mode);
    const std::complex<double> s{-5.0, 2.0 * std::numbers::pi * 0.9 * f};
    const auto g = a / (s - lambda) + std::conj(a) / (s - std::conj(lambda));
    QCOMPARE_LE(std::abs(g / receptance({mode}, s) - 1.0), 1e-12);
    const Mode back = modeFromResidue(lambda, a);
    QCOMPARE_LE(std::abs(back.stiffness_n_per_m / k - 1.0), 1e-12);
    QCOMPARE_LE(std::abs(back.natural_frequency_hz / f - 1.0), 1e-13);
  }

  void realPartOfResidueIgnored() {
    const Mode mode{500.0, 0.03, 2e7};
    const auto a = residueOf(mode) + std::complex<double>(1e-3 * std::abs(residueOf(mode)), 0.0);
    QCOMPARE_LE(std::abs(modeFromResidue(poleOf(mode), a).stiffness_n_per_m / 2e7 - 1.0), 1e-12);
  }

  void positiveImaginaryResidueGivesNegativeStiffness() {
    const Mode mode{500.0, 0.03, 2e7};
    QVERIFY(modeFromResidue(poleOf(mode), -residueOf(mode)).stiffness_n_per_m < 0.0);
  }
};

MX_REGISTER_TEST(TestModalPole)
#include "test_modal_pole.moc"
