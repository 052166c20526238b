// Significant stable poles become modes (mode_selection.h).
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
};

MX_REGISTER_TEST(TestModeSelection)
#include "test_mode_selection.moc"
