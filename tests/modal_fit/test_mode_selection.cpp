// Significant stable poles become modes; insignificant and duplicate modes go (mode_selection.h).
#include "modal_fit/frf_band.h"
#include "modal_fit/modal_pole.h"
#include "modal_fit/mode_selection.h"
#include "synthetic_frf.h"
#include "test_registry.h"

using namespace mx;

class TestModeSelection : public QObject {
  Q_OBJECT
 private slots:
  void dropsInsignificantAndKeepsTheLargest() {
    const ModalAxis truth{{500.0, 0.02, 2e7}, {1200.0, 0.03, 1e8}};
    const auto frf = test::syntheticFrf(truth, 200.0, 2000.0, 1801);
    const auto band = selectBand(frf.frequency_hz, frf.h_m_per_n, 200.0, 2000.0);
    const auto spurious = poleOf(Mode{800.0, 0.01, 1e7});  // no mode there: tiny residue
    const std::vector<std::complex<double>> poles{poleOf(truth[0]), spurious, poleOf(truth[1])};
    const auto automatic = selectPoles(band, poles, std::nullopt, 10);
    QCOMPARE(automatic.size(), std::size_t{2});
    QCOMPARE(automatic[0], poles[0]);  // ranked by 1 / (2 zeta k): 1.25e-6 and 1.7e-7 m/N
    QCOMPARE(automatic[1], poles[2]);
    const auto one = selectPoles(band, poles, 1, 10);
    QCOMPARE(one.size(), std::size_t{1});
    QCOMPARE(one[0], poles[0]);
    QCOMPARE(selectPoles(band, poles, std::nullopt, 1).size(), std::size_t{1});
    QVERIFY(selectPoles(band, {}, std::nullopt, 10).empty());
  }

  void significanceOfRefinedModes() {
    const ModalAxis truth{{500.0, 0.02, 2e7}, {1200.0, 0.03, 1e8}};
    const auto frf = test::syntheticFrf(truth, 200.0, 2000.0, 1801);
    const auto band = selectBand(frf.frequency_hz, frf.h_m_per_n, 200.0, 2000.0);
    QCOMPARE_LE(std::abs(resonanceAmplitude(truth[0]) - 1.25e-6), 1e-18);
    QCOMPARE_LE(std::abs(significance(band, truth[0]) - 1.0), 0.01);  // the mode is |H| at its peak
    const ModalAxis fitted{truth[0], {800.0, 0.02, 1e11}, truth[1], {1500.0, 0.02, -1e8}};
    QCOMPARE_LE(significance(band, fitted[1]), 0.05);
    const auto kept = significantModes(band, fitted);  // 800 Hz: ~2 % of |H|; 1500 Hz: k < 0
    QCOMPARE(kept.size(), std::size_t{2});
    QCOMPARE(kept[1].natural_frequency_hz, 1200.0);
  }

  void distinctModes_data() {
    QTest::addColumn<double>("second_hz");
    QTest::addColumn<int>("count");
    QTest::newRow("0.9 % apart, zeta 2 %: one") << 1009.0 << 1;
    QTest::newRow("1.1 % apart, zeta 2 %: two") << 1011.0 << 2;
    QTest::newRow("5 % apart: two") << 1050.0 << 2;
  }
  void distinctModes() {
    QFETCH(double, second_hz);
    QFETCH(int, count);
    const ModalAxis modes{{second_hz, 0.02, 5e7}, {1000.0, 0.02, 2e7}};
    const auto kept = mx::distinctModes(modes);
    QCOMPARE(static_cast<int>(kept.size()), count);
    QCOMPARE(kept[0].natural_frequency_hz, 1000.0);  // the larger amplitude (smaller k) stays; sorted
  }
};

MX_REGISTER_TEST(TestModeSelection)
#include "test_mode_selection.moc"
