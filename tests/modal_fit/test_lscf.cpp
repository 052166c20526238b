// LSCF poles of exact and noisy receptances (lscf.h).
#include <algorithm>

#include "core/invalid_input.h"
#include "modal_fit/frf_band.h"
#include "modal_fit/lscf.h"
#include "modal_fit/modal_pole.h"
#include "synthetic_frf.h"
#include "test_registry.h"

using namespace mx;
using mx::test::relativeError;

namespace {

// The pole nearest to the mode's pole.
std::complex<double> nearestPole(const std::vector<std::complex<double>>& poles, const Mode& mode) {
  const auto target = poleOf(mode);
  return *std::min_element(poles.begin(), poles.end(),
                           [&](auto a, auto b) { return std::abs(a - target) < std::abs(b - target); });
}

}  // namespace

class TestLscf : public QObject {
  Q_OBJECT
 private slots:
  void polesOfTwoModes_data() {
    QTest::addColumn<int>("order");
    QTest::addColumn<double>("noise");
    QTest::addColumn<bool>("uneven");
    QTest::addColumn<double>("frequency_tol");
    QTest::addColumn<double>("damping_tol");
    QTest::newRow("order 8, exact") << 8 << 0.0 << false << 1e-3 << 0.01;
    QTest::newRow("order 20, exact") << 20 << 0.0 << false << 1e-4 << 0.001;
    QTest::newRow("order 20, exact, uneven grid") << 20 << 0.0 << true << 1e-4 << 0.001;
    QTest::newRow("order 20, 2 % noise") << 20 << 0.02 << false << 2e-3 << 0.05;
  }
  void polesOfTwoModes() {
    QFETCH(int, order);
    QFETCH(double, noise);
    QFETCH(bool, uneven);
    QFETCH(double, frequency_tol);
    QFETCH(double, damping_tol);
    const ModalAxis truth{{700.0, 0.02, 2e7}, {1300.0, 0.03, 3e7}};
    const auto frf = test::syntheticFrf(truth, 200.0, 2000.0, 1801, noise, 3, uneven);
    const LscfEstimator lscf(selectBand(frf.frequency_hz, frf.h_m_per_n, 200.0, 2000.0), order);
    QCOMPARE(lscf.samplingInterval(), 1.0 / 4000.0);
    const auto poles = lscf.poles(order);
    QCOMPARE(poles.size(), static_cast<std::size_t>(order));
    for (const Mode& mode : truth) {
      const auto pole = nearestPole(poles, mode);
      QCOMPARE_LE(relativeError(poleFrequencyHz(pole), mode.natural_frequency_hz), frequency_tol);
      QCOMPARE_LE(relativeError(poleDampingRatio(pole), mode.damping_ratio), damping_tol);
    }
  }

  void orderOutsideRangeThrows() {
    const auto frf = test::syntheticFrf({{700.0, 0.02, 2e7}}, 200.0, 2000.0, 100);
    const LscfEstimator lscf(selectBand(frf.frequency_hz, frf.h_m_per_n, 200.0, 2000.0), 4);
    QVERIFY_THROWS_EXCEPTION(InvalidInput, lscf.poles(5));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, lscf.poles(0));
  }
};

MX_REGISTER_TEST(TestLscf)
#include "test_lscf.moc"
