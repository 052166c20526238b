// The admissible space Q of one tool: b_min and the depth grid, every stored point re-checked against
// every constraint independently, and the constraint that empties Q.
#include <cmath>

#include "core/invalid_input.h"
#include "expert/admissible_grid.h"
#include "expert/candidate_speeds.h"
#include "expert_fixtures.h"
#include "model/cutting_force.h"
#include "test_registry.h"

using namespace mx;

class TestAdmissibleGrid : public QObject {
  Q_OBJECT
 private slots:
  // R1, paper grid: b_min = 0.95 * 0.7597 mm (delta = 0.05 is negligible), depth step b_min / 10.
  void rubioR1Grid() {
    const AdmissibleGrid g(test::rubioR1(), test::rubioExpertSettings());
    QCOMPARE_LE(std::abs(g.minimumBorderDepth() * 1e3 - 0.95 * 0.7597), 0.002);
    QCOMPARE_LE(std::abs(g.depthStep() - g.minimumBorderDepth() / 10.0), 1e-15);
    QVERIFY(!g.empty());
    std::int64_t points = 0;
    for (std::size_t i = 0; i < g.cells().size(); ++i) {
      const GridCell& c = g.cells()[i];
      points += c.feed_count;
      QVERIFY(c.speed_security > 0.0);
      QVERIFY(c.depth_m < g.boundary().depthLimit(c.speed_rev_per_s));
      // the last feed is admissible, the next one is not (power or feed per tooth)
      const ExpertPoint last = g.point(i, c.feed_count);
      QVERIFY(g.isAdmissible(last.speed_rev_per_s, last.depth_m, last.feed_per_tooth_m));
      QVERIFY(!g.isAdmissible(last.speed_rev_per_s, last.depth_m, last.feed_per_tooth_m + g.feedStep()));
      // the cached power per feed is the static model's peak power
      const CutPerformance perf = evaluateCut(g.setup(), {last.speed_rev_per_s, last.depth_m, last.feed_per_tooth_m});
      QCOMPARE_LE(std::abs(perf.peak_power_w - last.power_w), 1e-9 * perf.peak_power_w);
      QCOMPARE_LE(std::abs(perf.mrr_m3_per_s - last.mrr_m3_per_s), 1e-9 * perf.mrr_m3_per_s);
    }
    QCOMPARE(points, g.pointCount());
    QCOMPARE(g.funnel().emptiedBy(), QConstraint::None);
    // at 5800 rpm the power limit b s_t <= 0.1364 mm^2 bounds the feeds
    const double bs_limit = 745.3 / peakPowerPerDepthFeed(g.setup(), 5800.0 / 60.0);
    QCOMPARE_LE(std::abs(bs_limit * 1e6 - 0.13635), 0.0005);
  }

  // R1 by its measured FRFs only (1 Hz lines, no modes), dynamics = Measured, delta = 0: the same b_min
  // within 1 %, and the Rule 7.2 speeds come from the FRFs' peak lines.
  void measuredFrfGrid() {
    MillingSetup r1 = test::rubioR1();
    r1.measured_x = test::sampledAxis(r1.modes_x, 0.0, 4000.0, 1.0);
    r1.measured_y = test::sampledAxis(r1.modes_y, 0.0, 4000.0, 1.0);
    r1.modes_x.clear();
    r1.modes_y.clear();
    ExpertSettings s = test::rubioExpertSettings();
    s.stability.delta_per_s = 0.0;
    s.stability.dynamics = DynamicsSource::Measured;
    const AdmissibleGrid g(r1, s);
    QCOMPARE_LE(std::abs(g.minimumBorderDepth() * 1e3 / (0.95 * 0.7597) - 1.0), 0.01);
    QVERIFY(!g.empty());
    QCOMPARE(g.speeds(), rankingSpeeds(r1, s.grid));
    QCOMPARE(static_cast<int>(g.speeds().size()), 6 + 27);  // 13 + 14 speeds 60 f / (3 k) in [800, 6000] rpm
    s.stability.method = StabilityMethod::SemiDiscretization;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, AdmissibleGrid(r1, s));
  }

  void emptiedBy_data() {
    QTest::addColumn<int>("which");
    QTest::addColumn<int>("expected");
    QTest::addColumn<QString>("text");
    QTest::newRow("spindle max") << 0 << int(QConstraint::SpindleSpeed) << "spindle speed maximum (500 rpm";
    QTest::newRow("feed per tooth") << 1 << int(QConstraint::FeedPerTooth) << "feed per tooth maximum (0.005 mm";
    QTest::newRow("feed drive") << 2 << int(QConstraint::FeedDrive) << "feed-drive maximum (0.01 mm/s)";
    QTest::newRow("power") << 3 << int(QConstraint::SpindlePower) << "spindle power limit (0.001 W)";
  }
  void emptiedBy() {
    QFETCH(int, which);
    QFETCH(int, expected);
    QFETCH(QString, text);
    ExpertSettings s = test::rubioExpertSettings();
    if (which == 0) s.limits.max_spindle_rev_per_s = 500.0 / 60.0;
    if (which == 1) s.limits.max_feed_per_tooth_m = 0.005e-3;
    if (which == 2) s.limits.max_feed_velocity_m_per_s = 0.01e-3;
    if (which == 3) s.limits.spindle_power_w = 0.001;
    const AdmissibleGrid g(test::rubioR1(), s);
    QVERIFY(g.empty());
    QCOMPARE(int(g.funnel().emptiedBy()), expected);
    const QString message = QString::fromStdString(describeConstraint(g.funnel().emptiedBy(), s));
    QVERIFY2(message.contains(text), qPrintable(message));
  }

  // A feed-drive limit removes exactly the feeds with s n_t N above it.
  void feedDriveLimit() {
    ExpertSettings s = test::rubioExpertSettings();
    s.limits.max_feed_velocity_m_per_s = 40e-3;  // 40 mm/s
    const AdmissibleGrid g(test::rubioR1(), s);
    QVERIFY(!g.empty());
    double top = 0.0;
    for (std::size_t i = 0; i < g.cells().size(); ++i) {
      const ExpertPoint p = g.point(i, g.cells()[i].feed_count);
      top = std::max(top, p.feed_per_tooth_m * 3 * p.speed_rev_per_s);
    }
    QVERIFY(top <= 40e-3 * (1 + 1e-9));
    QVERIFY(top > 40e-3 - 3 * 0.01e-3 * 100.0);  // the fastest speed reaches within one feed step
  }
};

MX_REGISTER_TEST(TestAdmissibleGrid)
#include "test_admissible_grid.moc"
