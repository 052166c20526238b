// The fitted receptance: modes plus residual terms (fit_model.h).
#include <numbers>

#include "modal_fit/fit_model.h"
#include "test_registry.h"

using namespace mx;
using C = std::complex<double>;

class TestFitModel : public QObject {
  Q_OBJECT
 private slots:
  void modesPlusResidualTerms_data() {
    QTest::addColumn<double>("f");
    QTest::newRow("low") << 10.0;
    QTest::newRow("resonance") << 700.0;
    QTest::newRow("high") << 5000.0;
  }
  void modesPlusResidualTerms() {
    QFETCH(double, f);
    const FittedModel model{{{700.0, 0.02, 2e7}}, {C(3e-3, 1e-4), C(2e-8, -1e-9)}};
    const double w = 2.0 * std::numbers::pi * f;
    const C expected = receptance(model.modes, {0.0, w}) - model.residuals.lower / (w * w) + model.residuals.upper;
    QCOMPARE_LE(std::abs(fittedReceptance(model, f) - expected), 1e-15 * std::abs(expected));
    const auto many = fittedReceptance(model, std::vector<double>{f, f});
    QCOMPARE(many.size(), std::size_t{2});
    QCOMPARE(many[1], fittedReceptance(model, f));
  }
};

MX_REGISTER_TEST(TestFitModel)
#include "test_fit_model.moc"
