// Levenberg-Marquardt refinement of a perturbed model back to the exact one (nlls_refinement.h).
#include "modal_fit/fit_error.h"
#include "modal_fit/frf_band.h"
#include "modal_fit/nlls_refinement.h"
#include "synthetic_frf.h"
#include "test_registry.h"

using namespace mx;
using mx::test::relativeError;

class TestNllsRefinement : public QObject {
  Q_OBJECT
 private slots:
  void convergesFromAPerturbedStart() {
    const ModalAxis truth{{600.0, 0.02, 2e7}, {630.0, 0.02, 3e7}, {1500.0, 0.04, 5e7}};
    const auto frf = test::syntheticFrf(truth, 300.0, 2000.0, 1701);
    const auto band = selectBand(frf.frequency_hz, frf.h_m_per_n, 300.0, 2000.0);
    FittedModel start{{{603.0, 0.022, 2.2e7}, {628.0, 0.018, 2.8e7}, {1490.0, 0.045, 4.6e7}}, {}};
    const FittedModel refined = refineModel(band, start);
    QCOMPARE(refined.modes.size(), truth.size());
    for (std::size_t r = 0; r < truth.size(); ++r) {
      QCOMPARE_LE(relativeError(refined.modes[r].natural_frequency_hz, truth[r].natural_frequency_hz), 1e-8);
      QCOMPARE_LE(relativeError(refined.modes[r].damping_ratio, truth[r].damping_ratio), 1e-6);
      QCOMPARE_LE(relativeError(refined.modes[r].stiffness_n_per_m, truth[r].stiffness_n_per_m), 1e-6);
    }
    QCOMPARE_LE(fitErrorPercent(band.h_m_per_n, fittedReceptance(refined, band.frequency_hz)), 1e-5);
  }

  void cancelledKeepsTheStart() {
    const auto frf = test::syntheticFrf({{600.0, 0.02, 2e7}}, 300.0, 2000.0, 200);
    const auto band = selectBand(frf.frequency_hz, frf.h_m_per_n, 300.0, 2000.0);
    const FittedModel start{{{610.0, 0.02, 2e7}}, {}};
    std::atomic<bool> cancel{true};
    const auto kept = refineModel(band, start, JobControl{&cancel, {}});
    QCOMPARE(kept.modes[0].natural_frequency_hz, 610.0);
  }
};

MX_REGISTER_TEST(TestNllsRefinement)
#include "test_nlls_refinement.moc"
