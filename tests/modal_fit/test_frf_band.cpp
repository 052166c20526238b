// The fitting band of a measured FRF (frf_band.h).
#include "modal_fit/frf_band.h"
#include "test_registry.h"

using namespace mx;
using C = std::complex<double>;

class TestFrfBand : public QObject {
  Q_OBJECT
 private slots:
  void keepsThePointsInsideTheBandAboveZero() {
    const std::vector<double> f{0.0, 10.0, 20.0, 30.0, 40.0};
    const std::vector<C> h{{1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}};
    const FrfBand band = selectBand(f, h, 0.0, 30.0);
    QCOMPARE(band.frequency_hz, (std::vector<double>{10.0, 20.0, 30.0}));
    QCOMPARE(band.h_m_per_n, (std::vector<C>{{2, 0}, {3, 0}, {4, 0}}));
    QCOMPARE(band.from_hz, 0.0);
    QCOMPARE(band.to_hz, 30.0);
    QCOMPARE_LE(std::abs(band.rmsMagnitude() - std::sqrt(29.0 / 3.0)), 1e-14);
  }
};

MX_REGISTER_TEST(TestFrfBand)
#include "test_frf_band.moc"
