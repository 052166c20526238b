// Eq. 13 terms and the deterministic order of candidate points (the tie rule).
#include <cmath>

#include "expert/tool_cost.h"
#include "test_registry.h"

using namespace mx;

class TestToolCost : public QObject {
  Q_OBJECT
 private slots:
  void terms() {
    const CostNormalisation nf{745.3, 2e-6, 20.0};
    const CostTerms t = toolCostTerms({0.2, 0.725, 0.075}, nf, 745.3 / 2.0, 1e-6, 5.0);
    QCOMPARE_LE(std::abs(t.power - 0.1), 1e-15);
    QCOMPARE_LE(std::abs(t.mrr - 1.45), 1e-15);
    QCOMPARE_LE(std::abs(t.speed_security - 0.3), 1e-15);
    QCOMPARE_LE(std::abs(t.total() - 1.85), 1e-14);
    // no power limit: the power term vanishes
    const CostTerms u = toolCostTerms({1.0, 0.0, 0.0}, {INFINITY, 1.0, 1.0}, 100.0, 1.0, 1.0);
    QCOMPARE(u.total(), 0.0);
  }

  void tieRule_data() {
    QTest::addColumn<QList<double>>("a");  // cost, mrr, power, speed, depth
    QTest::addColumn<QList<double>>("b");
    QTest::addColumn<bool>("aFirst");
    QTest::addColumn<bool>("bFirst");
    QTest::newRow("lower cost") << QList<double>{1.0, 1, 1, 1, 1} << QList<double>{1.1, 9, 0, 0, 0} << true << false;
    QTest::newRow("cost tie, higher MRR")
        << QList<double>{1.0, 2, 9, 9, 9} << QList<double>{1.0 + 1e-12, 1, 1, 1, 1} << true << false;
    QTest::newRow("then lower power") << QList<double>{1.0, 2, 1, 9, 9} << QList<double>{1.0, 2, 2, 1, 1} << true
                                      << false;
    QTest::newRow("then lower speed") << QList<double>{1.0, 2, 1, 5, 9} << QList<double>{1.0, 2, 1, 6, 1} << true
                                      << false;
    QTest::newRow("then lower depth") << QList<double>{1.0, 2, 1, 5, 1} << QList<double>{1.0, 2, 1, 5, 2} << true
                                      << false;
    QTest::newRow("all equal") << QList<double>{1.0, 2, 1, 5, 1} << QList<double>{1.0, 2, 1, 5, 1} << false << false;
    QTest::newRow("cost beyond tolerance")
        << QList<double>{1.0 + 1e-8, 9, 0, 0, 0} << QList<double>{1.0, 1, 1, 1, 1} << false << true;
  }
  void tieRule() {
    QFETCH(QList<double>, a);
    QFETCH(QList<double>, b);
    QFETCH(bool, aFirst);
    QFETCH(bool, bFirst);
    const RankKey ka{a[0], a[1], a[2], a[3], a[4]}, kb{b[0], b[1], b[2], b[3], b[4]};
    QCOMPARE(rankBefore(ka, kb), aFirst);
    QCOMPARE(rankBefore(kb, ka), bFirst);
  }
};

MX_REGISTER_TEST(TestToolCost)
#include "test_tool_cost.moc"
