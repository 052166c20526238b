// Weights on the simplex (validation messages) and the Rule 6 step.
#include <cmath>

#include "core/invalid_input.h"
#include "expert/cost_weights.h"
#include "test_registry.h"

using namespace mx;

class TestCostWeights : public QObject {
  Q_OBJECT
 private slots:
  void validation_data() {
    QTest::addColumn<std::vector<double>>("values");
    QTest::addColumn<QString>("error");  // empty: valid
    QTest::newRow("paper c") << std::vector<double>{0.2, 0.725, 0.075} << QString();
    QTest::newRow("vertex") << std::vector<double>{0.0, 0.0, 1.0} << QString();
    QTest::newRow("sum within 1e-6") << std::vector<double>{0.2, 0.7, 0.1000009} << QString();
    QTest::newRow("sum off by 2e-6") << std::vector<double>{0.2, 0.7, 0.100002} << QString("must sum to 1");
    QTest::newRow("sum 1.1") << std::vector<double>{0.3, 0.7, 0.1} << QString("must sum to 1");
    QTest::newRow("negative") << std::vector<double>{-0.1, 1.0, 0.1} << QString(">= 0");
    QTest::newRow("two values") << std::vector<double>{0.5, 0.5} << QString("must have 3 weights");
    QTest::newRow("nan") << std::vector<double>{NAN, 0.5, 0.5} << QString(">= 0");
  }
  void validation() {
    QFETCH(std::vector<double>, values);
    QFETCH(QString, error);
    try {
      validateSimplexWeights("c", values, 3);
      QVERIFY2(error.isEmpty(), "accepted weights that should be refused");
    } catch (const InvalidInput& e) {
      QVERIFY2(!error.isEmpty(), e.what());
      QVERIFY2(QString(e.what()).contains(error), e.what());
      QVERIFY(QString(e.what()).startsWith("c = ["));
    }
  }

  // Rule 6: 1 % of c2 moves to c3; c1 untouched; the sum stays 1 over 200 steps.
  void malfunctionStep_data() {
    QTest::addColumn<double>("c1");
    QTest::addColumn<double>("c2");
    QTest::newRow("paper") << 0.2 << 0.725;
    QTest::newRow("c2 only") << 0.0 << 1.0;
    QTest::newRow("no c2") << 0.6 << 0.0;
  }
  void malfunctionStep() {
    QFETCH(double, c1);
    QFETCH(double, c2);
    std::array<double, 3> c{c1, c2, 1.0 - c1 - c2};
    const auto once = mx::malfunctionStep(c);
    QCOMPARE_LE(std::abs(once[1] - 0.99 * c2), 1e-15);
    QCOMPARE_LE(std::abs(once[2] - (c[2] + 0.01 * c2)), 1e-15);
    QCOMPARE_LE(std::abs(once[0] - c1), 1e-15);
    for (int i = 0; i < 200; ++i) c = mx::malfunctionStep(c);
    QCOMPARE_LE(std::abs(c[0] + c[1] + c[2] - 1.0), 1e-12);
    for (double v : c) QVERIFY(v >= 0.0);
    QCOMPARE_LE(std::abs(c[1] - c2 * std::pow(0.99, 200)), 1e-12);
  }
};

MX_REGISTER_TEST(TestCostWeights)
#include "test_cost_weights.moc"
