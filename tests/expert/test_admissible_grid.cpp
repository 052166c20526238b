// The admissible space Q of one tool: b_min and the depth grid, every stored point re-checked against
// every constraint independently, and the constraint that empties Q.
#include <algorithm>
#include <cmath>
#include <numbers>

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
    const double bs_limit = 745.3 / (5800.0 / 60.0 * peakPerDepthFeed(g.setup(), 1e-3, 1e-4).power_w_per_rev_per_s);
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
    QTest::newRow("tool force") << 4 << int(QConstraint::ToolForce) << "tool force limit F_allow (0.001 N";
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
    if (which == 4) s.limits.max_tool_force_n = 0.001;
    const AdmissibleGrid g(test::rubioR1(), s);
    QVERIFY(g.empty());
    QCOMPARE(int(g.funnel().emptiedBy()), expected);
    const QString message = QString::fromStdString(describeConstraint(g.funnel().emptiedBy(), s));
    QVERIFY2(message.contains(text), qPrintable(message));
  }

  // A 1.5 N·m spindle with P_max = 745.3 W: P_av = 2 pi N 1.5 below the corner speed 745.3 / (2 pi 1.5)
  // = 79.08 rev/s (4745 rpm). R1 at full immersion peaks at P = pi D K_t N b s_t (5.655e7 N b s_t W).
  // At b = 0.5 mm (under b_min everywhere) and 1800 rpm: s_t = 0.3 mm takes 254.5 W <= 282.7 W
  // (1.35 N·m), s_t = 0.4 mm takes 339.3 W > 282.7 W (1.8 N·m): excluded, though P_max alone admits it.
  void torqueLineBoundsLowSpeeds() {
    ExpertSettings s = test::rubioExpertSettings();
    const AdmissibleGrid power_only(test::rubioR1(), s);
    s.limits.max_spindle_torque_nm = 1.5;
    const AdmissibleGrid g(test::rubioR1(), s);
    const double n = 1800.0 / 60.0;
    QCOMPARE_LE(std::abs(s.limits.spindlePower().available(n) - 282.743), 1e-3);
    QCOMPARE_LE(std::abs(evaluateCut(g.setup(), {n, 0.5e-3, 0.3e-3}).peak_power_w - 254.5), 0.1);
    QCOMPARE_LE(std::abs(evaluateCut(g.setup(), {n, 0.5e-3, 0.4e-3}).peak_power_w - 339.3), 0.1);
    QVERIFY(g.isAdmissible(n, 0.5e-3, 0.3e-3));
    QVERIFY(!g.isAdmissible(n, 0.5e-3, 0.4e-3));
    QVERIFY(power_only.isAdmissible(n, 0.5e-3, 0.4e-3));
    // Per cell: below the corner speed the feeds stop at the torque line, above it at P_max.
    const double corner = 745.3 / (2.0 * std::numbers::pi * 1.5);
    int torque_bound = 0, power_bound = 0;
    for (const GridCell& c : g.cells()) {
      const GridCell* same = nullptr;
      for (const GridCell& p : power_only.cells())
        if (p.speed_rev_per_s == c.speed_rev_per_s && p.depth_m == c.depth_m) same = &p;
      QVERIFY(same != nullptr);
      const double p_av = std::min(745.3, 2.0 * std::numbers::pi * c.speed_rev_per_s * 1.5);
      QCOMPARE_LE(std::abs(c.available_power_w - p_av), 1e-9);
      const int by_power = static_cast<int>(std::floor(p_av / (c.power_per_feed * g.feedStep()) * (1 + 1e-9)));
      QCOMPARE(c.feed_count, std::min(by_power, 55));  // 55: the feed per tooth maximum, 0.55 mm
      if (c.speed_rev_per_s < corner && c.feed_count < same->feed_count) ++torque_bound;
      if (c.speed_rev_per_s >= corner) {
        QCOMPARE(c.feed_count, same->feed_count);
        ++power_bound;
      }
    }
    QVERIFY(torque_bound > 0 && power_bound > 0);
    QVERIFY(g.pointCount() < power_only.pointCount());
  }

  // A power curve whose torque rises with speed (a gear range): rows (2000 rpm, 200 W) and
  // (6000 rpm, 2000 W) give 150 W at 1500 rpm (0.955 N·m, constant torque below the first row) and
  // 650 W at 3000 rpm (2.07 N·m). The cut b = 0.5 mm, s_t = 0.25 mm needs 1.125 N·m: 176.7 W at
  // 1500 rpm is excluded, the same cut at 3000 rpm (353.4 W <= 650 W and <= P_max) is admitted.
  void powerCurveAdmitsTheCutAtAHigherSpeed() {
    ExpertSettings s = test::rubioExpertSettings();
    s.limits.spindle_curve = {{2000.0 / 60.0, 200.0}, {6000.0 / 60.0, 2000.0}};
    const AdmissibleGrid g(test::rubioR1(), s);
    const double low = 1500.0 / 60.0, high = 3000.0 / 60.0;
    QCOMPARE_LE(std::abs(s.limits.spindlePower().available(low) - 150.0), 1e-9);
    QCOMPARE_LE(std::abs(s.limits.spindlePower().available(high) - 650.0), 1e-9);
    QCOMPARE_LE(std::abs(evaluateCut(g.setup(), {low, 0.5e-3, 0.25e-3}).peak_power_w - 176.7), 0.1);
    QCOMPARE_LE(std::abs(evaluateCut(g.setup(), {high, 0.5e-3, 0.25e-3}).peak_power_w - 353.4), 0.1);
    QVERIFY(!g.isAdmissible(low, 0.5e-3, 0.25e-3));
    QVERIFY(g.isAdmissible(high, 0.5e-3, 0.25e-3));
  }

  // Rule 3 (Module II): F_allow = 150 N on R1. The peak resultant is k_F b s_t, so each cell's feeds stop
  // at floor(F_allow / (k_F b feed_step)) or at the limits Q had without it; the next feed step of a
  // force-bound cell is refused for the force, and the force bounds cells that power alone admits.
  void toolForceLimitBoundsTheFeeds() {
    ExpertSettings s = test::rubioExpertSettings();
    const AdmissibleGrid unlimited(test::rubioR1(), s);
    s.limits.max_tool_force_n = 150.0;
    const AdmissibleGrid g(test::rubioR1(), s);
    const double k_force = peakPerDepthFeed(g.setup(), 1e-3, 1e-4).force_n;
    int force_bound = 0;
    for (std::size_t i = 0; i < g.cells().size(); ++i) {
      const GridCell& c = g.cells()[i];
      const GridCell* same = nullptr;
      for (const GridCell& u : unlimited.cells())
        if (u.speed_rev_per_s == c.speed_rev_per_s && u.depth_m == c.depth_m) same = &u;
      QVERIFY(same != nullptr);
      const int by_force = static_cast<int>(std::floor(150.0 / (k_force * c.depth_m * g.feedStep()) * (1 + 1e-9)));
      QCOMPARE(c.feed_count, std::min(same->feed_count, by_force));
      const ExpertPoint last = g.point(i, c.feed_count);
      QVERIFY(evaluateCut(g.setup(), {last.speed_rev_per_s, last.depth_m, last.feed_per_tooth_m}).peak_force_n <=
              150.0 * (1 + 1e-9));
      if (c.feed_count < same->feed_count) {
        ++force_bound;
        QCOMPARE(g.violation(last.speed_rev_per_s, last.depth_m, last.feed_per_tooth_m + g.feedStep()),
                 QConstraint::ToolForce);
      }
    }
    QVERIFY(force_bound > 0);
    QVERIFY(g.pointCount() < unlimited.pointCount());
    QCOMPARE_GE(g.funnel().power_points, g.funnel().force_points);
    QCOMPARE_GE(g.funnel().force_points, g.funnel().admissible_points);
    s.limits.max_tool_force_n = 0.0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, AdmissibleGrid(test::rubioR1(), s));
  }

  // A real cutter (R1 with a 30 deg helix and 6/-4 um runout), or R1 with edge forces: each cell's largest
  // feed keeps the exact peak power and force (evaluateCut) within the limits, and the next feed step breaks
  // one of them or another limit of Q (violation), so the per-depth lines and the exact check lose no point.
  // The power of a point (the chord of the peak power between the largest feed and half of it) is within
  // 2 % of the exact peak power at every fourth feed.
  void realCutterFeedsMeetTheExactLimits_data() {
    QTest::addColumn<bool>("runout");
    QTest::addColumn<double>("edge_n_per_m");
    QTest::newRow("30 deg helix, runout") << true << 0.0;
    QTest::newRow("edge forces K_te = K_re = 40 N/mm") << false << 40e3;
  }
  void realCutterFeedsMeetTheExactLimits() {
    QFETCH(bool, runout);
    QFETCH(double, edge_n_per_m);
    ExpertSettings s = test::rubioExpertSettings();
    s.limits.max_tool_force_n = 150.0;
    MillingSetup tool = test::rubioR1();
    if (runout) {
      tool.helix_rad = 30.0 * std::numbers::pi / 180.0;
      tool.runout_m = {0.0, 6e-6, -4e-6};
    }
    tool.tangential_edge_n_per_m = tool.radial_edge_n_per_m = edge_n_per_m;
    const AdmissibleGrid g(tool, s);
    QVERIFY(!g.cells().empty());
    double worst_power_error = 0.0;
    for (std::size_t i = 0; i < g.cells().size(); ++i) {
      const GridCell& c = g.cells()[i];
      const ExpertPoint last = g.point(i, c.feed_count);
      const CutPerformance perf = evaluateCut(tool, {last.speed_rev_per_s, last.depth_m, last.feed_per_tooth_m});
      for (int f = 1; f <= c.feed_count; f += 4) {
        const ExpertPoint q = g.point(i, f);
        const double exact = evaluateCut(tool, {q.speed_rev_per_s, q.depth_m, q.feed_per_tooth_m}).peak_power_w;
        worst_power_error = std::max(worst_power_error, std::abs(q.power_w / exact - 1.0));
      }
      QVERIFY(perf.peak_power_w <= c.available_power_w * (1 + 1e-6));
      QVERIFY(perf.peak_force_n <= 150.0 * (1 + 1e-6));
      QCOMPARE(g.violation(last.speed_rev_per_s, last.depth_m, last.feed_per_tooth_m), QConstraint::None);
      const double next = last.feed_per_tooth_m + g.feedStep();
      const CutPerformance np = evaluateCut(tool, {last.speed_rev_per_s, last.depth_m, next});
      QVERIFY2(g.violation(last.speed_rev_per_s, last.depth_m, next) != QConstraint::None,
               qPrintable(QString("n %1 b %2 count %3 P %4/%5 F %6")
                              .arg(last.speed_rev_per_s)
                              .arg(last.depth_m)
                              .arg(c.feed_count)
                              .arg(np.peak_power_w)
                              .arg(c.available_power_w)
                              .arg(np.peak_force_n)));
    }
    qInfo("largest power error of a point: %.3f %%", 100.0 * worst_power_error);
    QVERIFY(worst_power_error < 0.02);
  }

  void invalidCurveIsRefused() {
    ExpertSettings s = test::rubioExpertSettings();
    s.limits.spindle_curve = {{50.0, 200.0}, {40.0, 300.0}};
    QVERIFY_THROWS_EXCEPTION(InvalidInput, AdmissibleGrid(test::rubioR1(), s));
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
