// Lobe-geometry queries on a synthetic envelope whose answers are known by hand.
#include <cmath>

#include "core/invalid_input.h"
#include "stability/stability_boundary.h"
#include "test_registry.h"
#include "two_lobes_fixture.h"

using namespace mx;

using mx::test::twoLobes;

class TestStabilityBoundary : public QObject {
  Q_OBJECT
 private slots:
  void minimaAreFound() {
    const StabilityBoundary s(twoLobes());
    QCOMPARE(s.minima().size(), size_t{2});
    QCOMPARE_LE(std::abs(s.minima()[0].speed_rev_per_s - 100.0), 1e-9);
    QCOMPARE_LE(std::abs(s.minima()[1].depth_m - 2e-3), 1e-12);
  }

  void alphaScalesTheLimit() {
    const StabilityBoundary s(twoLobes(), 0.5);
    QCOMPARE_LE(std::abs(s.depthLimit(150.0) - 2.5e-3), 1e-9);
    QVERIFY(s.isStable(150.0, 2.4e-3));
    QVERIFY(!s.isStable(150.0, 2.6e-3));
  }

  // At the minimum of lobe A (b_lim = 1 mm) with alpha = 0.8: stable below 0.8 mm, marginal up to 1.05 mm.
  void verdictBands_data() {
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<QString>("verdict");
    QTest::newRow("well below alpha b_lim") << 0.5 << "stable";
    QTest::newRow("just below alpha b_lim") << 0.799999 << "stable";
    QTest::newRow("at alpha b_lim") << 0.8 << "marginal";
    QTest::newRow("on the lobe") << 1.0 << "marginal";
    QTest::newRow("just inside the band") << 1.049999 << "marginal";
    QTest::newRow("beyond the band") << 1.050001 << "unstable";
    QTest::newRow("far above") << 3.0 << "unstable";
  }
  void verdictBands() {
    QFETCH(double, depth_mm);
    QFETCH(QString, verdict);
    const StabilityBoundary s(twoLobes(), 0.8);
    QCOMPARE(QString(verdictKey(s.verdict(100.0, depth_mm * 1e-3))), verdict);
    QCOMPARE(s.verdict(100.0, depth_mm * 1e-3) == StabilityVerdict::Stable, s.isStable(100.0, depth_mm * 1e-3));
  }

  void speedSecurity_data() {
    QTest::addColumn<double>("speed");
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<double>("expected");
    // Pocket at 3 mm: A crosses at 100 + sqrt(1250) (14.645 left of 150), B at 200 - sqrt(833.3)
    // (21.13 right): the smaller side wins.
    QTest::newRow("pocket, both above minima") << 150.0 << 3.0 << 50.0 - std::sqrt(1250.0);
    // 1.5 mm at 120: above A's minimum -> crossing at 100 + sqrt(312.5); below B's minimum (2 mm)
    // -> distance to its speed, 80. Smaller: 20 - 17.678.
    QTest::newRow("left crossing nearer") << 120.0 << 1.5 << 20.0 - std::sqrt(312.5);
    QTest::newRow("below both minima") << 150.0 << 0.5 << 50.0;
    // Highest-speed lobe: only the left side (B's minimum at 200) counts.
    QTest::newRow("highest lobe, below minimum") << 240.0 << 1.0 << 40.0;
    QTest::newRow("unstable point") << 100.0 << 1.5 << 0.0;
  }
  void speedSecurity() {
    QFETCH(double, speed);
    QFETCH(double, depth_mm);
    QFETCH(double, expected);
    const StabilityBoundary s(twoLobes());
    // Linear interpolation on a 1 rev/s grid: crossings accurate to ~0.01 rev/s.
    QCOMPARE_LE(std::abs(s.speedSecurity(speed, depth_mm * 1e-3) - expected), 0.01);
  }

  // Scaled distance to the boundary, against a brute-force search over the polyline.
  void scaledDistanceMatchesBruteForce() {
    const LobeDiagram d = twoLobes();
    const StabilityBoundary s(d);
    const NormalisationSpans spans{170.0, 5e-3};
    for (double n : {90.0, 130.0, 175.0, 240.0}) {
      for (double b : {0.5e-3, 1.5e-3}) {
        double best = 1e300;
        for (int i = 0; i <= 170000; ++i) {
          const double ns = 80.0 + i * 1e-3;
          const double dn = (n - ns) / spans.speed_rev_per_s;
          const double db = (b - s.depthLimit(ns)) / spans.depth_m;
          best = std::min(best, std::hypot(dn, db));
        }
        const double dist = s.scaledDistance(n, b, spans);
        QCOMPARE_LE(std::abs(std::abs(dist) - best), 1e-6);
        QCOMPARE(dist > 0.0, s.isStable(n, b));
      }
    }
  }

  // ROS is the scaled distance in units of the point's own speed and depth.
  void robustnessIsRelativeToThePoint() {
    const StabilityBoundary s(twoLobes());
    for (double n : {90.0, 130.0, 175.0, 240.0})
      for (double b : {0.5e-3, 1.5e-3, 4e-3}) QCOMPARE(s.robustness(n, b), s.scaledDistance(n, b, {n, b}));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, s.robustness(100.0, 0.0));
  }

  // Analytic limit: under a flat boundary at b_lim, the nearest border point is straight above, so
  // ROS = (b_lim - b) / b, whatever the speed; above it, -(b - b_lim) / b.
  void robustnessUnderAFlatBoundary_data() {
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<double>("expected");
    QTest::newRow("half the limit") << 1.0 << 1.0;
    QTest::newRow("a tenth of the limit") << 0.2 << 9.0;
    QTest::newRow("90 % of the limit") << 1.8 << 0.2 / 1.8;
    QTest::newRow("10 % above the limit") << 2.2 << -0.2 / 2.2;
  }
  void robustnessUnderAFlatBoundary() {
    QFETCH(double, depth_mm);
    QFETCH(double, expected);
    LobeDiagram d;
    for (int n = 50; n <= 150; ++n) {
      d.speed_rev_per_s.push_back(n);
      d.envelope_depth_m.push_back(2e-3);
      d.envelope_chatter_hz.push_back(0.0);
    }
    QCOMPARE_LE(std::abs(StabilityBoundary(d).robustness(100.0, depth_mm * 1e-3) - expected), 1e-12);
  }

  void outsideRangeIsRefused() {
    const StabilityBoundary s(twoLobes());
    QVERIFY_THROWS_EXCEPTION(InvalidInput, s.depthLimit(10.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, StabilityBoundary(twoLobes(), 1.5));
  }
};

MX_REGISTER_TEST(TestStabilityBoundary)
#include "test_stability_boundary.moc"
