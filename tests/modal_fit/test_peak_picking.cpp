// Peak picking with the half-power bandwidth (peak_picking.h) on well-separated modes.
#include "modal_fit/frf_band.h"
#include "modal_fit/peak_picking.h"
#include "synthetic_frf.h"
#include "test_registry.h"

using namespace mx;
using mx::test::relativeError;

class TestPeakPicking : public QObject {
  Q_OBJECT
 private slots:
  // Looser tolerances than LSCF: frequency 0.5 %, damping 10 %, stiffness 10 %.
  void singleMode_data() {
    QTest::addColumn<double>("zeta");
    QTest::addColumn<double>("noise");
    QTest::newRow("1 %, exact") << 0.01 << 0.0;
    QTest::newRow("3 %, exact") << 0.03 << 0.0;
    QTest::newRow("3 %, 2 % noise") << 0.03 << 0.02;
  }
  void singleMode() {
    QFETCH(double, zeta);
    QFETCH(double, noise);
    const Mode mode{800.0, zeta, 2e7};
    const auto frf = test::syntheticFrf({mode}, 0.0, 1600.0, 3201, noise, 7);
    const auto modes = pickPeaks(selectBand(frf.frequency_hz, frf.h_m_per_n, 400.0, 1200.0), 3);
    QCOMPARE(modes.size(), std::size_t{1});
    QCOMPARE_LE(relativeError(modes[0].natural_frequency_hz, 800.0), 0.005);
    QCOMPARE_LE(relativeError(modes[0].damping_ratio, zeta), 0.10);
    QCOMPARE_LE(relativeError(modes[0].stiffness_n_per_m, 2e7), 0.10);
  }

  void twoSeparatedModesSortedByFrequency() {
    const ModalAxis truth{{600.0, 0.02, 3e7}, {1500.0, 0.03, 5e7}};
    const auto frf = test::syntheticFrf(truth, 100.0, 2000.0, 3801);
    const auto band = selectBand(frf.frequency_hz, frf.h_m_per_n, 100.0, 2000.0);
    const auto modes = pickPeaks(band, 5);
    QCOMPARE(modes.size(), std::size_t{2});
    for (std::size_t r = 0; r < 2; ++r) {
      QCOMPARE_LE(relativeError(modes[r].natural_frequency_hz, truth[r].natural_frequency_hz), 0.005);
      QCOMPARE_LE(relativeError(modes[r].damping_ratio, truth[r].damping_ratio), 0.10);
      QCOMPARE_LE(relativeError(modes[r].stiffness_n_per_m, truth[r].stiffness_n_per_m), 0.10);
    }
    const auto highest = pickPeaks(band, 1);  // the higher peak: 1 / (2 zeta k)
    QCOMPARE(highest.size(), std::size_t{1});
    QCOMPARE_LE(relativeError(highest[0].natural_frequency_hz, 600.0), 0.005);
  }

  void noPeakOnAMonotonicFrf() {
    const auto frf = test::syntheticFrf({{5000.0, 0.05, 1e7}}, 10.0, 1000.0, 200);
    QVERIFY(pickPeaks(selectBand(frf.frequency_hz, frf.h_m_per_n, 10.0, 1000.0), 3).empty());
  }
};

MX_REGISTER_TEST(TestPeakPicking)
#include "test_peak_picking.moc"
