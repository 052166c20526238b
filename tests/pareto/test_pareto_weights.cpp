// Rule 8 validation and both Rule 13 renormalisations keep the weights on the simplex.
#include <random>

#include "core/invalid_input.h"
#include "pareto/pareto_weights.h"
#include "test_registry.h"

using namespace mx;

class TestParetoWeights : public QObject {
  Q_OBJECT
 private slots:
  void validation_data() {
    QTest::addColumn<double>("w0");
    QTest::addColumn<double>("w1");
    QTest::addColumn<QString>("error");
    QTest::newRow("ok") << 0.5 << 0.3 << QString();
    QTest::newRow("negative") << -0.1 << 0.9 << QString(">= 0");
    QTest::newRow("sum") << 0.5 << 0.5 << QString("must sum to 1");
  }
  void validation() {
    QFETCH(double, w0);
    QFETCH(double, w1);
    QFETCH(QString, error);
    const ParetoWeights w{w0, w1, 0.1, 0.1};
    try {
      validateParetoWeights(w);
      QVERIFY(error.isEmpty());
    } catch (const InvalidInput& e) {
      QVERIFY2(!error.isEmpty() && QString(e.what()).contains(error) && QString(e.what()).startsWith("w = ["),
               e.what());
    }
  }
  void rule13StaysOnSimplex_data() {
    QTest::addColumn<unsigned>("seed");
    for (unsigned s = 1; s <= 5; ++s) QTest::newRow(qPrintable(QString("seed %1").arg(s))) << s;
  }
  void rule13StaysOnSimplex() {
    QFETCH(unsigned, seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.5, 1.5);
    for (int i = 0; i < 1000; ++i) {
      const ParetoWeights raw{u(rng), u(rng), u(rng), u(rng)};
      QVERIFY(onSimplex(renormaliseBySum(raw)));
      const auto k = static_cast<Objective>(i % 4);
      const ParetoWeights kept = renormaliseKeeping(raw, k);
      QVERIFY(onSimplex(kept));
      if (raw[index(k)] >= 0.0 && raw[index(k)] <= 1.0) QCOMPARE(kept[index(k)], raw[index(k)]);
    }
  }
  // Variant 2 keeps the proportions of the other weights.
  void keepingProportions() {
    const ParetoWeights w = withWeight({0.4, 0.1, 0.3, 0.2}, Objective::Mrr, 0.55);
    QVERIFY(onSimplex(w));
    QCOMPARE(w[1], 0.55);
    QVERIFY(std::abs(w[0] / w[2] - 0.4 / 0.3) < 1e-12);
    QVERIFY(std::abs(w[0] / w[3] - 0.4 / 0.2) < 1e-12);
    const ParetoWeights z = withWeight({0.0, 1.0, 0.0, 0.0}, Objective::Mrr, 0.4);
    QVERIFY(onSimplex(z));
    QCOMPARE(z[0], 0.2);
  }
};

MX_REGISTER_TEST(TestParetoWeights)
#include "test_pareto_weights.moc"
