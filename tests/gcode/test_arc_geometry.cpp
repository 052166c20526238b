// Arc geometry: radius arcs on both sides of the chord, tangential arcs, and their refusals.
#include <cmath>
#include <numbers>

#include "gcode/arc_geometry.h"
#include "test_registry.h"

using namespace mx;

class TestArcGeometry : public QObject {
  Q_OBJECT
 private slots:
  // From (0,0) to (20,20), radius 20: the quarter circles about (20,0) or (0,20), the three-quarter
  // circles about the other.
  void centreFromRadius_data() {
    QTest::addColumn<double>("radius");
    QTest::addColumn<bool>("clockwise");
    QTest::addColumn<double>("cx");
    QTest::addColumn<double>("cy");
    QTest::addColumn<double>("turns");
    QTest::newRow("cw, at most half a turn") << 20.0 << true << 20.0 << 0.0 << 0.25;
    QTest::newRow("ccw, at most half a turn") << 20.0 << false << 0.0 << 20.0 << 0.25;
    QTest::newRow("cw, more than half a turn") << -20.0 << true << 0.0 << 20.0 << 0.75;
    QTest::newRow("ccw, more than half a turn") << -20.0 << false << 20.0 << 0.0 << 0.75;
  }
  void centreFromRadius() {
    QFETCH(double, radius);
    QFETCH(bool, clockwise);
    QFETCH(double, cx);
    QFETCH(double, cy);
    QFETCH(double, turns);
    const auto c = arc::centreFromRadius({0, 0}, {20, 20}, radius, clockwise);
    QVERIFY(c.has_value());
    QVERIFY(std::abs((*c)[0] - cx) < 1e-12 && std::abs((*c)[1] - cy) < 1e-12);
    const double expected = turns * 2.0 * std::numbers::pi * 20.0;
    QVERIFY(std::abs(arc::length({0, 0}, {20, 20}, *c, clockwise) - expected) < 1e-9);
  }
  void halfCircleAndTooShortRadius() {
    const auto half = arc::centreFromRadius({0, 0}, {10, 0}, 5.0, true);
    QVERIFY(half && std::abs((*half)[0] - 5.0) < 1e-12 && std::abs((*half)[1]) < 1e-12);
    QVERIFY(!arc::centreFromRadius({0, 0}, {10, 0}, 4.99, true));
    QVERIFY(!arc::centreFromRadius({1, 1}, {1, 1}, 5.0, true));
  }
  void fullCircle() {
    QVERIFY(std::abs(arc::length({10, 0}, {10, 0}, {0, 0}, false) - 2.0 * std::numbers::pi * 10.0) < 1e-9);
  }
  // Leaving (0,0) along +X to (10,10): the quarter circle about (0,10), counter-clockwise; to (10,-10)
  // clockwise about (0,-10); straight ahead there is no arc.
  void tangentArc() {
    const auto left = arc::tangentArc({0, 0}, {10, 10}, {1, 0});
    QVERIFY(left.has_value());
    QVERIFY(!left->clockwise);
    QVERIFY(std::abs(left->centre[0]) < 1e-12 && std::abs(left->centre[1] - 10.0) < 1e-12);
    QVERIFY(std::abs(left->length - 5.0 * std::numbers::pi) < 1e-9);
    const auto right = arc::tangentArc({0, 0}, {10, -10}, {1, 0});
    QVERIFY(right && right->clockwise && std::abs(right->centre[1] + 10.0) < 1e-12);
    // Turning back: from (0,0) along +X to (0,20) is a half circle of radius 10.
    const auto back = arc::tangentArc({0, 0}, {0, 20}, {1, 0});
    QVERIFY(back && std::abs(back->length - 10.0 * std::numbers::pi) < 1e-9);
    QVERIFY(!arc::tangentArc({0, 0}, {10, 0}, {1, 0}));
  }
};

MX_REGISTER_TEST(TestArcGeometry)
#include "test_arc_geometry.moc"
