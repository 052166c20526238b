// Machining modules A-L (Landers & Ulsoy, Table 1) on a hand-filled context: feedrate routine, feed hold,
// force signal processor, contact monitor, automatic chatter detector, chatter suppressor and routine,
// estimator with the adaptive controller, and the model-based controller.
#include <cmath>

#include "supervisor/machining_modules.h"
#include "test_registry.h"

using namespace mx;

namespace {
MachiningContext context() {
  MachiningContext c;
  c.passes_m = {2e-3};
  c.reference_force_N = 150.0;
  return c;
}
void fill(MachiningContext& c, double amplitude_tooth, double amplitude_chatter) {
  c.fy_samples.clear();
  for (int j = 0; j < 80; ++j) {
    const double ph = 2.0 * M_PI * j / 80.0;
    c.fy_samples.push_back(-150.0 + amplitude_tooth * std::cos(4.0 * ph) + amplitude_chatter * std::sin(23.0 * ph));
  }
}
}  // namespace

class TestMachiningModules : public QObject {
  Q_OBJECT
 private slots:
  void periodsAndLetters() {
    const auto m = makeStandardModules();
    QCOMPARE(m.size(), std::size_t(11));  // F runs inside G
    for (const auto& x : m) {
      if (std::string("ABE").find(x->letter()) != std::string::npos)
        QVERIFY(x->period() == 0.010 || x->period() == 0.040);
      if (std::string("HIJKL").find(x->letter()) != std::string::npos) QCOMPARE(x->period(), 0.040);
    }
  }

  void feedrateRoutine() {
    MachiningContext c = context();
    FeedrateRoutine a;
    a.run(c);
    QCOMPARE(c.commanded_feed_m_per_s, 10e-3);
    c.override_valid = true;
    c.override_feed_m_per_s = 7e-3;
    a.run(c);
    QCOMPARE(c.commanded_feed_m_per_s, 7e-3);
    FeedHold hold;
    hold.run(c);
    a.run(c);
    QCOMPARE(c.commanded_feed_m_per_s, 0.0);
    hold.deactivate(c);
    a.run(c);
    QCOMPARE(c.commanded_feed_m_per_s, 7e-3);
  }

  void forceSignalAndContact() {
    MachiningContext c = context();
    fill(c, 40.0, 0.0);
    ForceSignalProcessor i;
    ContactMonitor j;
    i.run(c);
    QVERIFY(std::abs(c.F_Y_N - 190.0) < 1e-9);
    j.run(c);
    QVERIFY(c.b);
    c.fy_samples.assign(80, 10.0);
    i.run(c);
    j.run(c);
    QVERIFY(!c.b);
  }

  void chatterDetector() {
    MachiningContext c = context();
    AutomaticChatterDetector e;
    fill(c, 60.0, 0.0);  // forced response only: tooth harmonics
    QVERIFY(AutomaticChatterDetector::nonHarmonicAmplitude(c.fy_samples, 4) < 1e-9);
    e.run(c);
    QVERIFY(!c.d);
    fill(c, 60.0, 50.0);  // 575 Hz component
    QVERIFY(std::abs(AutomaticChatterDetector::nonHarmonicAmplitude(c.fy_samples, 4) - 50.0) < 1e-6);
    e.run(c);
    QVERIFY(c.d);
    e.reset(c);  // E*: cleared, and blind for one revolution of fresh samples
    QVERIFY(!c.d);
    e.run(c);
    QVERIFY(!c.d);
    c.t_s += 0.041;
    e.run(c);
    QVERIFY(c.d);
  }

  void suppressionRoutine() {
    MachiningContext c = context();
    c.d = true;
    ChatterSuppressionRoutine g;
    g.run(c);
    QCOMPARE(c.passes_m.size(), std::size_t(2));
    QCOMPARE(c.passes_m[0], 1e-3);
    QCOMPARE(c.passes_m[1], 1e-3);
    QVERIFY(c.replanned && c.feed_hold && !c.e);
    c.t_s = 0.1;
    g.run(c);
    QVERIFY(c.feed_hold && !c.e);
    c.t_s = 0.2;
    g.run(c);
    QVERIFY(!c.feed_hold && c.e && !c.d);
    QCOMPARE(c.passes_m.size(), std::size_t(2));  // one re-plan per activation
    g.deactivate(c);
    QVERIFY(!c.e);
  }

  void adaptiveControllerConverges() {
    // Process F_Y = 380 f^0.63 (K d^b at 1 mm ~ unknown to the controller): the loop settles at F_ref.
    MachiningContext c = context();
    ParameterEstimator h;
    AdaptiveForceController k;
    FeedrateRoutine a;
    k.reset(c);
    for (int n = 0; n < 20; ++n) {
      const double f_mm = c.commanded_feed_m_per_s / (4 * 25.0) * 1e3;
      c.feed_samples.assign(80, c.commanded_feed_m_per_s);
      c.F_Y_N = 380.0 * std::pow(f_mm, 0.63);
      h.run(c);
      k.run(c);
      a.run(c);
    }
    QVERIFY(c.gain_valid);
    QVERIFY(std::abs(c.estimated_gain - 380.0) < 1.0);
    const double f_mm = c.commanded_feed_m_per_s / (4 * 25.0) * 1e3;
    QVERIFY(std::abs(380.0 * std::pow(f_mm, 0.63) - 150.0) < 1.0);
    k.reset(c);  // K*: estimate restarts
    QVERIFY(!c.gain_valid && !c.override_valid);
  }

  void modelBasedController() {
    MachiningContext c = context();
    c.passes_m = {1e-3, 1e-3};
    ModelBasedForceModule l;
    l.reset(c);  // L* at contact: the loop restarts from the model's feed for F_ref at 1 mm
    QVERIFY(!c.override_valid);
    c.F_Y_N = 150.0;  // at the reference: the feed stays
    l.run(c);
    QVERIFY(c.override_valid);
    const double f0 = c.override_feed_m_per_s;
    QVERIFY(std::abs(760.0 * std::pow(f0 / (4 * 25.0) * 1e3, 0.63) - 150.0) < 1e-9);
    // 20 % over the reference: ln f drops by (1 - p)/a ln 1.2, p = exp(-40 ms / 200 ms).
    c.F_Y_N = 180.0;
    l.run(c);
    const double p = std::exp(-0.2);
    QVERIFY(std::abs(std::log(c.override_feed_m_per_s / f0) + (1.0 - p) / 0.63 * std::log(1.2)) < 1e-12);
    l.deactivate(c);
    QVERIFY(!c.override_valid);
  }
  void modelBasedControllerRestartsBumplessly() {
    MachiningContext c = context();
    c.commanded_feed_m_per_s = 10e-3;
    ModelBasedForceModule l({PowerLawForceModel{}, 0.2, ResetFeed::Current});
    l.reset(c);
    c.F_Y_N = 150.0;
    l.run(c);
    QCOMPARE(c.override_feed_m_per_s, 10e-3);  // the programmed feed the axis was moving at
  }
};

MX_REGISTER_TEST(TestMachiningModules)
#include "test_machining_modules.moc"
