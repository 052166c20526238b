// Relative RMS fit error over the band (fit_error.h).
#include <cmath>

#include "core/invalid_input.h"
#include "modal_fit/fit_error.h"
#include "test_registry.h"

using namespace mx;
using C = std::complex<double>;

class TestFitError : public QObject {
  Q_OBJECT
 private slots:
  void values_data() {
    QTest::addColumn<double>("offset");
    QTest::addColumn<double>("expected");
    QTest::newRow("exact") << 0.0 << 0.0;
    QTest::newRow("1 %") << 0.01 << 1.0;
    QTest::newRow("double") << 1.0 << 100.0;
  }
  void values() {
    QFETCH(double, offset);
    QFETCH(double, expected);
    const std::vector<C> h{{1e-6, 2e-6}, {-3e-6, 0.5e-6}, {0.0, -1e-7}};
    std::vector<C> fit;
    fit.reserve(h.size());
    for (const C& x : h) fit.push_back(x * C(1.0 + offset, 0.0));  // |H_fit - H| = offset |H|
    QCOMPARE_LE(std::abs(fitErrorPercent(h, fit) - expected), 1e-12);
  }

  void edgeCases() {
    QCOMPARE(fitErrorPercent({}, {}), 0.0);
    QVERIFY(std::isinf(fitErrorPercent({C(0.0, 0.0)}, {C(1.0, 0.0)})));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, fitErrorPercent({C(1.0, 0.0)}, {}));
  }
};

MX_REGISTER_TEST(TestFitError)
#include "test_fit_error.moc"
