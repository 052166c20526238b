// RollingMean: the mean of the last `window` values pushed, as a running sum.
#include <cmath>
#include <numbers>

#include "supervisor/rolling_mean.h"
#include "test_registry.h"

using namespace mx;

class TestRollingMean : public QObject {
  Q_OBJECT
 private slots:
  // Window 3 over 1, 2, 3, 4, 5: the mean of what is held, then of the last three.
  void knownSequence() {
    RollingMean mean(3);
    const double values[] = {1.0, 2.0, 3.0, 4.0, 5.0};
    const double expected[] = {1.0, 1.5, 2.0, 3.0, 4.0};
    for (int i = 0; i < 5; ++i) {
      mean.push(values[i]);
      QCOMPARE(mean.mean(), expected[i]);
    }
    QCOMPARE(mean.size(), std::size_t{3});
    QCOMPARE(mean.window(), std::size_t{3});
  }

  void windowOfOneIsTheLastValue() {
    RollingMean mean(1);
    for (double v : {4.0, -2.5, 7.25}) {
      mean.push(v);
      QCOMPARE(mean.mean(), v);
      QCOMPARE(mean.size(), std::size_t{1});
    }
  }

  void emptyIsNaN() { QVERIFY(std::isnan(RollingMean(4).mean())); }

  // A constant signal: the running sum keeps the mean at the constant to roundoff.
  void constantSignal() {
    RollingMean mean(7);
    for (int i = 0; i < 1000; ++i) mean.push(0.1);
    QVERIFY(std::abs(mean.mean() - 0.1) < 1e-15);
  }

  // A window of one full period of a sinusoid averages it out (analytic mean 0); of a linear ramp it
  // gives the midpoint of the window.
  void analyticMeans() {
    const int n = 40;
    RollingMean sine(n);
    for (int i = 0; i < 5 * n + 13; ++i) sine.push(std::sin(2.0 * std::numbers::pi * i / n));
    QVERIFY(std::abs(sine.mean()) < 1e-13);

    RollingMean ramp(10);
    for (int i = 0; i <= 100; ++i) ramp.push(static_cast<double>(i));
    QCOMPARE(ramp.mean(), 95.5);  // mean of 91 .. 100
  }
};

MX_REGISTER_TEST(TestRollingMean)
#include "test_rolling_mean.moc"
