// Eq. 13 terms and the deterministic order of candidate points (the tie rule).
#include <cmath>
#include <numbers>

#include "expert/tool_cost.h"
#include "test_registry.h"

using namespace mx;

class TestToolCost : public QObject {
  Q_OBJECT
 private slots:
  void terms() {
    CostNormalisation nf;
    nf.available_power.max_power_w = 745.3;
    nf.max_mrr_m3_per_s = 2e-6;
    nf.max_speed_security = 20.0;
    const CostTerms t = toolCostTerms({0.2, 0.725, 0.075}, nf, 100.0, 745.3 / 2.0, 1e-6, 5.0);
    QCOMPARE_LE(std::abs(t.power - 0.1), 1e-15);
    QCOMPARE_LE(std::abs(t.mrr - 1.45), 1e-15);
    QCOMPARE_LE(std::abs(t.speed_security - 0.3), 1e-15);
    QCOMPARE_LE(std::abs(t.total() - 1.85), 1e-14);
    // no power limit: the power term vanishes
    CostNormalisation unlimited;
    unlimited.max_mrr_m3_per_s = 1.0;
    unlimited.max_speed_security = 1.0;
    const CostTerms u = toolCostTerms({1.0, 0.0, 0.0}, unlimited, 100.0, 100.0, 1.0, 1.0);
    QCOMPARE(u.total(), 0.0);
  }

  // P_av is taken at the point's speed: with a 9 N·m torque, 2 pi 10 9 = 565.49 W at 10 rev/s (600 rpm),
  // so the same 282.74 W costs c1 / 2 there and c1 * 282.74 / 745.3 above the base speed (13.18 rev/s).
  void powerTermAtThePointsSpeed() {
    CostNormalisation nf;
    nf.available_power.max_power_w = 745.3;
    nf.available_power.max_torque_nm = 9.0;
    nf.max_mrr_m3_per_s = 1.0;
    nf.max_speed_security = 1.0;
    const double p = 0.5 * 2.0 * std::numbers::pi * 10.0 * 9.0;
    QCOMPARE_LE(std::abs(toolCostTerms({1.0, 0.0, 0.0}, nf, 10.0, p, 1.0, 1.0).power - 0.5), 1e-12);
    QCOMPARE_LE(std::abs(toolCostTerms({1.0, 0.0, 0.0}, nf, 20.0, p, 1.0, 1.0).power - 282.7433 / 745.3), 1e-6);
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
