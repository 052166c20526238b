// Which limit of Q one more step of depth or feed breaks (case study grid): at the largest-MRR point
// the lobes stop the depth and the feed drive the feed; well inside Q nothing binds.
#include "expert/limits_at_point.h"
#include "pareto/pareto_fixtures.h"
#include "test_registry.h"

using namespace mx;

class TestLimitsAtPoint : public QObject {
  Q_OBJECT
 private slots:
  void largestMrrPoint() {
    const AdmissibleGrid& g = test::paretoCaseGrid();
    ExpertPoint best{};
    for (std::size_t c = 0; c < g.cells().size(); ++c) {
      const ExpertPoint p = g.point(c, g.cells()[c].feed_count);
      if (p.mrr_m3_per_s > best.mrr_m3_per_s) best = p;
    }
    const LimitsAtPoint l = limitsAtPoint(g, best.speed_rev_per_s, best.depth_m, best.feed_per_tooth_m);
    QCOMPARE(l.depth, QConstraint::Stability);
    QVERIFY(l.feed == QConstraint::FeedDrive || l.feed == QConstraint::FeedPerTooth);
    QCOMPARE_LE(std::abs(l.next_depth_m - best.depth_m - g.depthStep()), 1e-15);
    QCOMPARE(std::string(constraintKey(l.depth)), std::string("stability"));
  }

  void insideNothingBinds() {
    const AdmissibleGrid& g = test::paretoCaseGrid();
    // 3000 rpm, two depth steps, 0.05 mm/tooth: far from every limit.
    const LimitsAtPoint l = limitsAtPoint(g, 50.0, 2.0 * g.depthStep(), 0.05e-3);
    QCOMPARE(l.depth, QConstraint::None);
    QCOMPARE(l.feed, QConstraint::None);
  }

  void violationOrder_data() {
    QTest::addColumn<double>("speed_rpm");
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<double>("feed_mm");
    QTest::addColumn<int>("expected");
    QTest::newRow("admissible") << 3000.0 << 0.2 << 0.05 << int(QConstraint::None);
    QTest::newRow("above the lobes") << 3000.0 << 5.0 << 0.05 << int(QConstraint::Stability);
    QTest::newRow("feed per tooth") << 1000.0 << 0.2 << 0.31 << int(QConstraint::FeedPerTooth);
    QTest::newRow("feed drive") << 5000.0 << 0.2 << 0.2 << int(QConstraint::FeedDrive);
    QTest::newRow("zero depth") << 3000.0 << 0.0 << 0.05 << int(QConstraint::OutsideGrid);
  }
  void violationOrder() {
    QFETCH(double, speed_rpm);
    QFETCH(double, depth_mm);
    QFETCH(double, feed_mm);
    QFETCH(int, expected);
    QCOMPARE(int(test::paretoCaseGrid().violation(speed_rpm / 60.0, depth_mm * 1e-3, feed_mm * 1e-3)), expected);
  }
};

MX_REGISTER_TEST(TestLimitsAtPoint)
#include "test_limits_at_point.moc"
