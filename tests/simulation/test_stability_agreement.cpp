// Time-domain simulation (RK4, seed eq. 1-7) against semi-discretization: the depth at which eta
// (seed eq. 11) crosses 1.3 lies within 10 % of the SDM b_lim at 6 or more speeds; for real cutters
// (variable pitch, helix) the linear limit lies within 5 %; and the delta
// margin (Rule 1.1): just below the delta = 50 1/s lobe, perturbations decay at rate delta or faster;
// and both methods raise the limit alike with process damping.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "simulation/simulation.h"
#include "stability/semi_discretization.h"
#include "support/fixtures.h"
#include "support/test_constants.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::kDeg;
double etaAt(const MillingSetup& s, double rev_per_s, double depth) {
  SimulationOptions o;
  o.revolutions = 300;  // slow growth near the boundary at zeta = 1.1 % needs a long run
  o.record_every = 1000000;
  return simulateMilling(s, {rev_per_s, depth, 1e-4}, o).indicators.eta;
}

// Smallest depth where eta >= 1.3, by bisection between a stable and a chattering depth.
double etaThresholdDepth(const MillingSetup& s, double rev_per_s, double guess) {
  double lo = 0.5 * guess, hi = 2.0 * guess;
  if (etaAt(s, rev_per_s, lo) >= 1.3 || etaAt(s, rev_per_s, hi) < 1.3) return -1.0;
  for (int i = 0; i < 9; ++i) {
    const double mid = 0.5 * (lo + hi);
    (etaAt(s, rev_per_s, mid) >= 1.3 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}
// Growth rate [1/s] of the homogeneous solution at depth b: two runs that differ only by a 1e-8 m initial
// displacement (on x, or on y when x is rigid); their difference is the transient (the model is linear while every
// tooth cuts), whose peak per revolution is fitted over revolutions 10-30 (after the start, before a chattering run's
// contact loss saturates it).
double transientGrowthRate(const MillingSetup& s, double rev_per_s, double depth, int revolutions) {
  const bool kick_x = !s.modes_x.empty();  // an axis with no mode is rigid and takes no initial displacement
  SimulationOptions a;
  a.revolutions = revolutions;
  a.evaluated_revolutions = 2;
  a.divergence_limit_m = 1.0;
  const SimulationResult base = simulateMilling(s, {rev_per_s, depth, 1e-4}, a);
  (kick_x ? a.initial_x_m : a.initial_y_m) = 1e-8;
  const SimulationResult kicked = simulateMilling(s, {rev_per_s, depth, 1e-4}, a);
  const std::size_t per_rev = base.trace.size() / static_cast<std::size_t>(base.simulated_revolutions);
  std::vector<double> logpeak;
  for (std::size_t k = 0; (k + 1) * per_rev <= base.trace.size(); ++k) {
    double peak = 0.0;
    for (std::size_t j = k * per_rev; j < (k + 1) * per_rev; ++j)
      peak =
          std::max(peak, std::hypot(kicked.trace.x_m[j] - base.trace.x_m[j], kicked.trace.y_m[j] - base.trace.y_m[j]));
    logpeak.push_back(std::log(std::max(peak, 1e-300)));
  }
  constexpr std::size_t kFirst = 10, kLast = 30;
  return (logpeak[kLast] - logpeak[kFirst]) * rev_per_s / static_cast<double>(kLast - kFirst);
}

}  // namespace

class TestStabilityAgreement : public QObject {
  Q_OBJECT
 private slots:
  void etaThresholdMatchesSdm_data() {
    QTest::addColumn<int>("tool");
    QTest::newRow("Rubio R1 (3 teeth, full immersion, up)") << 1;
    QTest::newRow("Insperger (2 teeth, full immersion, down)") << 2;
  }
  void etaThresholdMatchesSdm() {
    QFETCH(int, tool);
    const MillingSetup s = tool == 1 ? test::rubioR1() : test::insperger(1.0);
    const std::vector<double> rpm = tool == 1 ? std::vector<double>{4000, 5000, 6000, 7000, 8500, 10000}
                                              : std::vector<double>{6000, 8000, 10000, 12000, 15000, 17000, 19000};
    std::vector<double> speeds;
    speeds.reserve(rpm.size());
    for (double n : rpm) speeds.push_back(n / 60.0);
    SdmOptions o;
    o.steps_per_period = 60;
    o.depth_tolerance = 1e-3;
    const LobeDiagram sdm = computeSdmLobes(s, speeds, o);
    int agreeing = 0;
    for (size_t i = 0; i < speeds.size(); ++i) {
      const double blim = sdm.envelope_depth_m[i];
      QVERIFY(std::isfinite(blim));
      const double td = etaThresholdDepth(s, speeds[i], blim);
      const double rel = td > 0 ? td / blim - 1.0 : 1.0;
      qInfo("%6.0f rpm: SDM b_lim %.4f mm, eta = 1.3 at %.4f mm (%+.1f %%)", rpm[i], blim * 1e3, td * 1e3, rel * 100);
      if (std::abs(rel) < 0.10) ++agreeing;
    }
    // At 6 or more speeds. Insperger at 19000 rpm (flip lobe, b_lim 2.68 mm) is not among them:
    // the start from rest throws the teeth out of the cut and the model jumps to a coexisting chatter
    // state at ~2.12 mm, 21 % below the linear limit (subcritical; docs/fidelity.md).
    QVERIFY2(agreeing >= 6, qPrintable(QString("%1 of %2 speeds within 10 %").arg(agreeing).arg(speeds.size())));
  }

  // Real cutters: the SDM's b_lim (default accuracy) lies within 5 % of the time-domain model's linear
  // limit: the transient decays at 0.95 b_lim and grows at 1.05 b_lim, at 6 or more of 8 speeds. The
  // speeds avoid large b_lim, where the forced vibration of the unequal teeth throws them out of the cut
  // (contact loss, which the linear SDM does not model): 85/95 deg at 11000 and 13000 rpm (b_lim 1.8
  // and 3.0 mm) then decays on both sides.
  void realCuttersMatchSdm_data() {
    QTest::addColumn<int>("tool");
    QTest::newRow("85/95/85/95 deg pitch, 4 teeth, slot") << 1;
    QTest::newRow("30 deg helix, 2 teeth, a/D = 0.05") << 2;
  }
  void realCuttersMatchSdm() {
    QFETCH(int, tool);
    MillingSetup s;
    std::vector<double> rpm;
    if (tool == 1) {
      s = test::makeSetup(4, 0.020, 6e8, 1.0 / 3.0, test::insperger(1.0).modes_x, {}, MillingDirection::Down, 1.0);
      s.pitch_rad = {85 * kDeg, 95 * kDeg, 85 * kDeg, 95 * kDeg};
      rpm = {9000, 11000, 13000, 15000, 17000, 19000, 21000, 23000};
    } else {
      s = test::insperger(0.05);
      s.helix_rad = 30 * kDeg;
      rpm = {6000, 8000, 12000, 12500, 18000, 21000, 22500, 24000};
    }
    std::vector<double> speeds;
    speeds.reserve(rpm.size());
    for (double n : rpm) speeds.push_back(n / 60.0);
    const LobeDiagram sdm = computeSdmLobes(s, speeds, {});
    int agreeing = 0;
    for (size_t i = 0; i < speeds.size(); ++i) {
      const double blim = sdm.envelope_depth_m[i];
      QVERIFY(std::isfinite(blim));
      const double below = transientGrowthRate(s, speeds[i], 0.95 * blim, 31);
      const double above = transientGrowthRate(s, speeds[i], 1.05 * blim, 31);
      qInfo("%6.0f rpm: SDM b_lim %.4f mm; transient growth %.1f 1/s at 0.95 b_lim, %.1f 1/s at 1.05 b_lim", rpm[i],
            blim * 1e3, below, above);
      if (below < 0.0 && above > 0.0) ++agreeing;
    }
    QVERIFY2(agreeing >= 6, qPrintable(QString("%1 of %2 speeds within 5 %").arg(agreeing).arg(speeds.size())));
  }

  // Two runs that differ only in the initial displacement: their difference is the homogeneous
  // (transient) solution, which just below the delta-lobe decays like exp(-delta t) or faster.
  void deltaMarginDecayRate() {
    const MillingSetup s = test::insperger(1.0);
    const double delta = 50.0;
    for (double rpm : {9000.0, 13000.0}) {
      const double n = rpm / 60.0;
      SdmOptions o;
      o.steps_per_period = 60;
      o.delta_per_s = delta;
      const double b_delta = computeSdmLobes(s, {n}, o).envelope_depth_m.front();
      QVERIFY(std::isfinite(b_delta));
      const double b = 0.98 * b_delta;
      SimulationOptions a;
      a.revolutions = 40;
      a.evaluated_revolutions = 10;
      a.steps_per_tooth_period = 60;
      const SimulationResult base = simulateMilling(s, {n, b, 1e-4}, a);
      a.initial_x_m = 1e-7;
      const SimulationResult kicked = simulateMilling(s, {n, b, 1e-4}, a);
      // Peak |difference| per tooth period, and the decay rate fitted over the run.
      const int m = base.steps_per_tooth_period;
      const double T = 1.0 / (n * s.teeth);
      std::vector<double> t, logpeak;
      for (size_t k = 2; (k + 1) * m < base.trace.size(); ++k) {
        double peak = 0.0;
        for (size_t j = k * m; j < (k + 1) * m; ++j)
          peak = std::max(peak, std::abs(kicked.trace.x_m[j] - base.trace.x_m[j]));
        if (peak < 1e-15) break;
        t.push_back(k * T);
        logpeak.push_back(std::log(peak));
      }
      QVERIFY(t.size() > 20);
      const double rate = -(logpeak.back() - logpeak.front()) / (t.back() - t.front());
      qInfo("%6.0f rpm: b = 0.98 b_delta = %.4f mm, transient decay rate %.1f 1/s (delta = %.0f)", rpm, b * 1e3, rate,
            delta);
      QVERIFY2(rate >= 0.95 * delta, qPrintable(QString("decay rate %1 < delta %2").arg(rate).arg(delta)));
    }
  }

  // Process damping (docs/fidelity.md, "Process damping") in both methods: one mode on y, 4 teeth slotting,
  // 600 rpm (V = 0.31 m/s), C_i = 1e4 N/m raises the SDM limit by about 40 %. Between the two limits the
  // time domain decays with process damping and grows without it; 10 % above the raised limit it grows.
  void processDampingRaisesTheLimitInBothMethods() {
    MillingSetup s = test::makeSetup(4, 0.010, 6e8, 0.3, {}, {{300.0, 0.01, 5e6}}, MillingDirection::Down, 1.0);
    const double n = 10.0;
    SdmOptions o;
    o.depth_tolerance = 1e-4;
    const double plain = computeSdmLobes(s, {n}, o).envelope_depth_m.front();
    s.process_damping_n_per_m = 1e4;
    const double damped = computeSdmLobes(s, {n}, o).envelope_depth_m.front();
    QVERIFY2(damped > 1.3 * plain, qPrintable(QString("%1 vs %2 mm").arg(damped * 1e3).arg(plain * 1e3)));
    const double between = 0.5 * (plain + damped);
    const double with_damping = transientGrowthRate(s, n, between, 32);
    const double above = transientGrowthRate(s, n, 1.1 * damped, 32);
    s.process_damping_n_per_m = 0.0;
    const double without = transientGrowthRate(s, n, between, 32);
    qInfo("growth rates [1/s] at %.3f mm: %.2f with C_i, %.2f without; at %.3f mm with C_i: %.2f", between * 1e3,
          with_damping, without, 1.1 * damped * 1e3, above);
    QVERIFY(with_damping < 0.0);
    QVERIFY(without > 0.0);
    QVERIFY(above > 0.0);
  }
};

MX_REGISTER_TEST(TestStabilityAgreement)
#include "test_stability_agreement.moc"
