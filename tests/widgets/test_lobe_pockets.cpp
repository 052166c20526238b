// Stability pockets: on an envelope of V-shaped lobes (b = m_k + s |N - c_k|) the pockets are the
// intersections of neighbouring lobes, known in closed form; ripples below the prominence, the range
// ends, NaN (no limit) and plateaus. The envelope's linear interpolation.
#include <QTest>
#include <cmath>
#include <limits>

#include "lobe_pockets.h"
#include "support/test_constants.h"
#include "test_registry.h"

using mx::widgets::findStabilityPockets;

namespace {

constexpr double kSlope = 0.001;  // mm/rpm
using mx::test::kNaN;

// Lobes at 1000, 2000, 3000, 4000 rpm with minima 0.2, 0.5, 0.3, 0.45 mm, sampled every 5 rpm on
// [0, 5000]. Neighbours k, k+1 meet at N = (m_{k+1} - m_k + s (c_k + c_{k+1})) / 2s:
// 1650 rpm (0.85 mm), 2400 rpm (0.9 mm), 3575 rpm (0.875 mm).
void vLobes(QVector<double>& speed, QVector<double>& depth) {
  const double centre[] = {1000.0, 2000.0, 3000.0, 4000.0};
  const double minimum[] = {0.2, 0.5, 0.3, 0.45};
  for (int j = 0; j <= 1000; ++j) {
    const double n = 5.0 * j;
    double b = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) b = std::min(b, minimum[k] + kSlope * std::abs(n - centre[k]));
    speed.push_back(n);
    depth.push_back(b);
  }
}

}  // namespace

class TestLobePockets : public QObject {
  Q_OBJECT

 private slots:
  void pocketsAreTheLobeIntersectionsDeepestFirst() {
    QVector<double> speed, depth;
    vLobes(speed, depth);
    const auto pockets = findStabilityPockets(speed, depth);
    QCOMPARE(pockets.size(), 3);  // the rising range ends (1.2 mm at 0, 1.45 mm at 5000 rpm) are not pockets
    const double expected[][2] = {{2400.0, 0.9}, {3575.0, 0.875}, {1650.0, 0.85}};
    for (int i = 0; i < 3; ++i) {
      QCOMPARE(pockets[i].speed_rpm, expected[i][0]);
      QCOMPARE_LE(std::abs(pockets[i].depth_mm - expected[i][1]), 1e-12);
    }
  }

  // A ripple of 1 % on a lobe's flank is no pocket at the default 2 % prominence, and is one at 0.5 %.
  void ripplesBelowTheProminenceAreNoPockets() {
    const QVector<double> speed{0, 10, 20, 30, 40, 50, 60, 70};
    const QVector<double> depth{1.0, 0.8, 0.6, 0.606, 0.6, 0.7, 1.0, 0.9};
    QCOMPARE(findStabilityPockets(speed, depth).size(), 1);  // 60 rpm, 1.0 mm
    QCOMPARE(findStabilityPockets(speed, depth).front().speed_rpm, 60.0);
    QCOMPARE(findStabilityPockets(speed, depth, 0.005).size(), 2);
  }

  // NaN (no limit below the lobes' cap) is higher ground: a rise into it is no peak.
  void aRiseIntoNoLimitIsNoPocket() {
    const QVector<double> speed{0, 10, 20, 30, 40};
    const QVector<double> depth{0.5, 0.4, 0.6, kNaN, 0.5};
    QVERIFY(findStabilityPockets(speed, depth).isEmpty());
  }

  void aPlateauCountsOnceAtItsMiddle() {
    const QVector<double> speed{0, 10, 20, 30, 40, 50};
    const QVector<double> depth{0.1, 0.5, 0.5, 0.5, 0.2, 0.3};
    const auto pockets = findStabilityPockets(speed, depth);
    QCOMPARE(pockets.size(), 1);
    QCOMPARE(pockets.front().speed_rpm, 20.0);
    QCOMPARE(pockets.front().depth_mm, 0.5);
  }

  void shortOrEmptyEnvelopesHaveNone() {
    QVERIFY(findStabilityPockets({}, {}).isEmpty());
    QVERIFY(findStabilityPockets({1.0, 2.0}, {0.5, 0.4}).isEmpty());
  }

  void envelopeAt_data() {
    QTest::addColumn<double>("speed");
    QTest::addColumn<double>("expected");  // NaN: none
    QTest::newRow("sample") << 1000.0 << 0.2;
    QTest::newRow("between samples") << 1302.5 << 0.5025;
    QTest::newRow("first speed") << 0.0 << 1.2;
    QTest::newRow("last speed") << 5000.0 << 1.45;
    QTest::newRow("below the range") << -1.0 << kNaN;
    QTest::newRow("above the range") << 5000.5 << kNaN;
    QTest::newRow("NaN speed") << kNaN << kNaN;
  }
  void envelopeAt() {
    QFETCH(double, speed);
    QFETCH(double, expected);
    QVector<double> speeds, depth;
    vLobes(speeds, depth);
    const double b = mx::widgets::envelopeAt(speeds, depth, speed);
    if (std::isnan(expected))
      QVERIFY(std::isnan(b));
    else
      QCOMPARE_LE(std::abs(b - expected), 1e-12);
  }

  void nextToNoLimitTheEnvelopeIsNone() {
    const QVector<double> speed{0, 10, 20};
    const QVector<double> depth{0.5, kNaN, 0.5};
    QVERIFY(std::isnan(mx::widgets::envelopeAt(speed, depth, 5.0)));
    QCOMPARE(mx::widgets::envelopeAt(speed, depth, 0.0), 0.5);
  }
};

MX_REGISTER_TEST(TestLobePockets)
#include "test_lobe_pockets.moc"
