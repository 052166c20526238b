// The model-based force loop (Landers & Ulsoy's module L): integral action on ln f with the model's feed
// exponent places the closed-loop pole at p = exp(-T/tau) whatever the process gain, and removes the
// model's error at steady state.
#include <cmath>
#include <limits>

#include "control/model_based_force_loop.h"
#include "core/invalid_input.h"
#include "test_registry.h"

using namespace mx;

namespace {

constexpr double kSpeed = 25.0;  // 1500 rpm [rev/s]
constexpr double kDepth = 1e-3;

ModelBasedForceLoopSettings landersLoop(double tau_s, ResetFeed reset = ResetFeed::Current) {
  ModelBasedForceLoopSettings s;
  s.controller.reference_force_N = 150.0;
  s.time_constant_s = tau_s;
  s.reset_feed = reset;
  return s;
}

// The true process: the model's law with K scaled by `gain_error` (the model is wrong by that factor).
double process(double feed_rate_m_per_s, double gain_error) {
  const double f_mm = feed_rate_m_per_s / (4 * kSpeed) * 1e3;
  return gain_error * 760.0 * std::pow(kDepth * 1e3, 0.65) * std::pow(f_mm, 0.63);
}

}  // namespace

class TestModelBasedForceLoop : public QObject {
  Q_OBJECT
 private slots:
  void poleOfTheClosedLoop_data() {
    QTest::addColumn<double>("tau_s");
    QTest::addColumn<double>("gain_error");
    QTest::newRow("tau 40 ms, exact model") << 0.04 << 1.0;
    QTest::newRow("tau 200 ms, model 25 % high") << 0.2 << 0.8;
    QTest::newRow("tau 1 s, model 30 % low") << 1.0 << 1.3;
  }
  void poleOfTheClosedLoop() {
    // The force of a period answers the feed of the period before: ln(F/F_ref) shrinks by p each period.
    QFETCH(double, tau_s);
    QFETCH(double, gain_error);
    ModelBasedForceLoop loop(landersLoop(tau_s));
    const double p = std::exp(-0.04 / tau_s);
    QVERIFY(std::abs(loop.pole() - p) < 1e-15);
    loop.reset(10e-3, kDepth, kSpeed);
    double error = std::log(process(loop.feedRate(), gain_error) / 150.0);
    for (int k = 0; k < 30; ++k) {
      const double F = process(loop.feedRate(), gain_error);
      loop.update(F, kSpeed);
      const double next = std::log(process(loop.feedRate(), gain_error) / 150.0);
      QVERIFY2(std::abs(next - p * error) < 1e-12, qPrintable(QString("period %1").arg(k)));
      error = next;
    }
  }
  void integralActionRemovesTheModelError() {
    ModelBasedForceLoop loop(landersLoop(0.2));
    loop.reset(10e-3, kDepth, kSpeed);
    for (int k = 0; k < 400; ++k) loop.update(process(loop.feedRate(), 0.7), kSpeed);
    QVERIFY(std::abs(process(loop.feedRate(), 0.7) - 150.0) < 1e-9);
  }
  void resetFeeds() {
    ModelBasedForceLoop current(landersLoop(0.2, ResetFeed::Current));
    current.reset(10e-3, kDepth, kSpeed);
    QCOMPARE(current.feedRate(), 10e-3);  // bumpless: the programmed feed the axis moves at
    current.reset(80e-3, kDepth, kSpeed);
    QCOMPARE(current.feedRate(), 36e-3);  // clamped to the feed drive
    ModelBasedForceLoop model(landersLoop(0.2, ResetFeed::Model));
    model.reset(10e-3, kDepth, kSpeed);
    // (150 / 760)^(1/0.63) mm/tooth * 4 teeth * 25 rev/s = 7.6129 mm/s, the model's force is F_ref
    QVERIFY(std::abs(process(model.feedRate(), 1.0) - 150.0) < 1e-9);
    QVERIFY(std::abs(model.feedRate() * 1e3 - 100.0 * std::pow(150.0 / 760.0, 1.0 / 0.63)) < 1e-12);
  }
  void noWindUpAtTheFeedLimit() {
    // A process too weak to reach F_ref even at the drive's 36 mm/s: the feed sits at the maximum.
    ModelBasedForceLoop loop(landersLoop(0.2));
    loop.reset(10e-3, kDepth, kSpeed);
    for (int k = 0; k < 200; ++k) loop.update(process(loop.feedRate(), 0.2), kSpeed);
    QCOMPARE(loop.feedRate(), 36e-3);
    // The process stiffens (deeper material): the very next period already lowers the feed.
    loop.update(process(loop.feedRate(), 1.0), kSpeed);
    QVERIFY(loop.feedRate() < 36e-3 * 0.99);
  }
  void noChipHoldsTheFeed() {
    ModelBasedForceLoop loop(landersLoop(0.2));
    loop.reset(10e-3, kDepth, kSpeed);
    QCOMPARE(loop.update(0.0, kSpeed), 10e-3);
    QCOMPARE(loop.update(std::nan(""), kSpeed), 10e-3);
  }
  void badSettingsNameTheField_data() {
    QTest::addColumn<double>("period_s");
    QTest::addColumn<double>("tau_s");
    QTest::addColumn<double>("min_fraction");
    QTest::addColumn<QString>("field");
    QTest::newRow("period 0") << 0.0 << 0.2 << 1e-3 << "period";
    QTest::newRow("tau negative") << 0.04 << -1.0 << 1e-3 << "time_constant";
    QTest::newRow("tau infinite") << 0.04 << std::numeric_limits<double>::infinity() << 1e-3 << "time_constant";
    QTest::newRow("min fraction 2") << 0.04 << 0.2 << 2.0 << "min_feed_fraction";
  }
  void badSettingsNameTheField() {
    QFETCH(double, period_s);
    QFETCH(double, tau_s);
    QFETCH(double, min_fraction);
    QFETCH(QString, field);
    ModelBasedForceLoopSettings s = landersLoop(0.2);
    s.period_s = period_s;
    s.time_constant_s = tau_s;
    s.min_feed_fraction = min_fraction;
    try {
      ModelBasedForceLoop loop(s);
      QFAIL("accepted");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString(e.what()).contains(field + " = "), e.what());
    }
  }
  void resetFeedNames() {
    QCOMPARE(parseResetFeed("model"), ResetFeed::Model);
    QCOMPARE(parseResetFeed(resetFeedName(ResetFeed::Current)), ResetFeed::Current);
    QVERIFY_THROWS_EXCEPTION(InvalidInput, parseResetFeed("programmed"));
  }
};

MX_REGISTER_TEST(TestModelBasedForceLoop)
#include "test_model_based_force_loop.moc"
