// LSFD residues for known poles and the modal stiffness from the residue (lsfd.h, modal_pole.h).
#include "modal_fit/frf_band.h"
#include "modal_fit/lsfd.h"
#include "modal_fit/modal_pole.h"
#include "synthetic_frf.h"
#include "test_registry.h"

using namespace mx;
using mx::test::relativeError;

class TestLsfd : public QObject {
  Q_OBJECT
 private slots:
  // k = -w^2 / (2 w_d Im A) exact on one exact mode: 1e-9 relative.
  void stiffnessExactOnOneMode_data() {
    QTest::addColumn<double>("f");
    QTest::addColumn<double>("zeta");
    QTest::addColumn<double>("k");
    QTest::newRow("light") << 750.0 << 0.005 << 2e7;
    QTest::newRow("typical") << 750.0 << 0.03 << 5.6e6;
    QTest::newRow("heavy") << 750.0 << 0.2 << 1e8;
  }
  void stiffnessExactOnOneMode() {
    QFETCH(double, f);
    QFETCH(double, zeta);
    QFETCH(double, k);
    const Mode mode{f, zeta, k};
    const auto frf = test::syntheticFrf({mode}, 300.0, 1200.0, 901);
    const auto band = selectBand(frf.frequency_hz, frf.h_m_per_n, 300.0, 1200.0);
    const auto fit = fitResidues(band, {poleOf(mode)});
    QCOMPARE(fit.residues.size(), std::size_t{1});
    QCOMPARE_LE(std::abs(fit.residues[0] / residueOf(mode) - 1.0), 1e-9);
    const auto model = fittedModel({poleOf(mode)}, fit);
    QCOMPARE_LE(relativeError(model.modes[0].stiffness_n_per_m, k), 1e-9);
    QCOMPARE_LE(relativeError(model.modes[0].natural_frequency_hz, f), 1e-12);
    QCOMPARE_LE(relativeError(model.modes[0].damping_ratio, zeta), 1e-12);
    const double h_peak = 1.0 / (2.0 * zeta * k);
    QCOMPARE_LE(std::abs(fit.residuals.upper) / h_peak, 1e-9);
  }

  // An out-of-band mode above the band is taken by the upper residual (compliance ~ 1/k).
  void residualTermsTakeOutOfBandModes() {
    const ModalAxis truth{{500.0, 0.02, 2e7}, {900.0, 0.03, 3e7}, {5000.0, 0.05, 4e7}};
    const auto frf = test::syntheticFrf(truth, 300.0, 1200.0, 901);
    const auto band = selectBand(frf.frequency_hz, frf.h_m_per_n, 300.0, 1200.0);
    const auto fit = fitResidues(band, {poleOf(truth[0]), poleOf(truth[1])});
    const auto model = fittedModel({poleOf(truth[0]), poleOf(truth[1])}, fit);
    for (std::size_t r = 0; r < 2; ++r)
      QCOMPARE_LE(relativeError(model.modes[r].stiffness_n_per_m, truth[r].stiffness_n_per_m), 0.01);
    QCOMPARE_LE(relativeError(fit.residuals.upper.real(), 1.0 / 4e7), 0.1);
  }
};

MX_REGISTER_TEST(TestLsfd)
#include "test_lsfd.moc"
