// SpeedGrid: the speeds of a lobe computation, from `from` in steps up to `to`; a range of a whole
// number of steps ends at `to` itself, so that a point at the top speed is inside the lobes.
#include "stability/lobe_diagram.h"
#include "stability/stability_boundary.h"
#include "test_registry.h"

using namespace mx;

class TestLobeDiagram : public QObject {
  Q_OBJECT
 private slots:
  void speedGridEnds_data() {
    QTest::addColumn<double>("from_rpm");
    QTest::addColumn<double>("to_rpm");
    QTest::addColumn<double>("step_rpm");
    QTest::addColumn<int>("count");
    QTest::addColumn<double>("last_rpm");
    // 400 / 60 + 260 (10 / 60) rounds to 1 ulp below 50 rev/s without the snap.
    QTest::newRow("400-3000 by 10") << 400.0 << 3000.0 << 10.0 << 261 << 3000.0;
    QTest::newRow("1000-12000 by 10") << 1000.0 << 12000.0 << 10.0 << 1101 << 12000.0;
    QTest::newRow("800-6000 by 10") << 800.0 << 6000.0 << 10.0 << 521 << 6000.0;
    QTest::newRow("not a whole number of steps") << 400.0 << 3005.0 << 10.0 << 261 << 3000.0;
    QTest::newRow("one speed") << 3000.0 << 3000.0 << 10.0 << 1 << 3000.0;
  }
  void speedGridEnds() {
    QFETCH(double, from_rpm);
    QFETCH(double, to_rpm);
    QFETCH(double, step_rpm);
    QFETCH(int, count);
    QFETCH(double, last_rpm);
    const std::vector<double> speeds = SpeedGrid{from_rpm / 60.0, to_rpm / 60.0, step_rpm / 60.0}.values();
    QCOMPARE(static_cast<int>(speeds.size()), count);
    QCOMPARE(speeds.front(), from_rpm / 60.0);
    QCOMPARE_LE(std::abs(speeds.back() * 60.0 - last_rpm), 1e-9);
    if (last_rpm == to_rpm) QCOMPARE(speeds.back(), to_rpm / 60.0);
  }

  // The top speed of a grid is a speed of its lobes.
  void topSpeedIsCovered() {
    LobeDiagram d;
    d.speed_rev_per_s = SpeedGrid{400.0 / 60.0, 3000.0 / 60.0, 10.0 / 60.0}.values();
    d.envelope_depth_m.assign(d.speed_rev_per_s.size(), 1e-3);
    d.envelope_chatter_hz.assign(d.speed_rev_per_s.size(), 0.0);
    const StabilityBoundary boundary(d, 1.0);
    QVERIFY(boundary.covers(3000.0 / 60.0));
    QCOMPARE(boundary.depthLimit(3000.0 / 60.0), 1e-3);
  }
};

MX_REGISTER_TEST(TestLobeDiagram)
#include "test_lobe_diagram.moc"
