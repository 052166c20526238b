// DelayHistory: the ring buffer of past displacements and its cubic Hermite interpolation (used for the
// delayed term x(t - T) of seed eq. 7).
#include <cmath>
#include <stdexcept>

#include "simulation/delay_history.h"
#include "test_registry.h"

using namespace mx;

namespace {
// p(t) = 1 + 2t - 3t^2 + 0.5t^3 (per axis scaled), a cubic: Hermite interpolation must be exact.
double p(double t) {
  return 1.0 + 2.0 * t - 3.0 * t * t + 0.5 * t * t * t;
}
double dp(double t) {
  return 2.0 - 6.0 * t + 1.5 * t * t;
}
}  // namespace

class TestDelayHistory : public QObject {
  Q_OBJECT
 private slots:
  void hermiteIsExactForCubics_data() {
    QTest::addColumn<double>("u");
    QTest::newRow("on a sample") << 3.0;
    QTest::newRow("quarter") << 3.25;
    QTest::newRow("half") << 5.5;
    QTest::newRow("near the next sample") << 6.999999;
    QTest::newRow("last interval") << 8.9;
  }
  void hermiteIsExactForCubics() {
    QFETCH(double, u);
    const double dt = 0.1;
    DelayHistory history(dt, 16);
    for (int i = 0; i < 10; ++i) history.push({p(i * dt), -2.0 * p(i * dt), dp(i * dt), -2.0 * dp(i * dt)});
    const AxisPosition v = history.interpolate(u);
    QVERIFY(std::abs(v.x - p(u * dt)) < 1e-13);
    QVERIFY(std::abs(v.y + 2.0 * p(u * dt)) < 1e-13);
  }

  void midpointMatchesInterpolation() {
    const double dt = 2e-5;
    DelayHistory history(dt, 8);
    for (int i = 0; i < 6; ++i)
      history.push({std::sin(700.0 * i * dt), std::cos(900.0 * i * dt), 700.0 * std::cos(700.0 * i * dt),
                    -900.0 * std::sin(900.0 * i * dt)});
    for (int i = 0; i < 5; ++i) {
      const AxisPosition a = history.midpoint(i), b = history.interpolate(i + 0.5);
      QCOMPARE(a.x, b.x);
      QCOMPARE(a.y, b.y);
      // 4th-order accurate for a smooth signal: error ~ (w dt)^4 / 384 = 1e-10.
      QVERIFY(std::abs(a.x - std::sin(700.0 * (i + 0.5) * dt)) < 1e-9);
    }
  }

  void preHistoryIsZero() {
    DelayHistory history(1.0, 4);
    history.push({1.0, 2.0, 0.0, 0.0});
    QCOMPARE(history.at(-1).x, 0.0);
    QCOMPARE(history.at(-5).vy, 0.0);
    QCOMPARE(history.position(0).y, 2.0);
    // Between the zero pre-history sample -1 and sample 0 (zero slopes): h01(0.5) = 0.5.
    QCOMPARE(history.interpolate(-0.5).x, 0.5);
  }

  void ringKeepsTheLookback() {
    const std::int64_t lookback = 10;
    DelayHistory history(1.0, lookback);
    QVERIFY(history.capacity() >= lookback + 4);
    QCOMPARE(history.capacity() & (history.capacity() - 1), std::int64_t{0});  // power of two
    for (int i = 0; i < 1000; ++i) history.push({double(i), 0.0, 1.0, 0.0});
    QCOMPARE(history.size(), std::int64_t{1000});
    for (std::int64_t i = 999 - lookback; i <= 999; ++i) QCOMPARE(history.at(i).x, double(i));
    QCOMPARE(history.interpolate(995.25).x, 995.25);  // a line is reproduced exactly
  }

  void rejectsInvalidArguments() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, DelayHistory(0.0, 4));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, DelayHistory(1.0, 0));
  }
};

MX_REGISTER_TEST(TestDelayHistory)
#include "test_delay_history.moc"
