// The time-domain simulation with the real cutter geometry (docs/fidelity.md, "Real cutters"):
// per-tooth delays for variable pitch, axial slices for the helix, runout in the chip - checked
// against the uniform straight cutter it must reduce to, the static chip rule, slice convergence,
// the constant- and variable-speed kernels, and the CVODE reference.
#include <QElapsedTimer>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "core/invalid_input.h"
#include "model/cutting_force.h"
#include "simulation/simulation.h"
#include "simulation/time_domain_simulator.h"
#include "support/fixtures.h"
#include "support/test_constants.h"
#include "support/vector_compare.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::kDeg;
using mx::test::kPi;

using mx::test::maxRelativeDifference;

double traceDifference(const SimulationTrace& a, const SimulationTrace& b) {
  return std::max({maxRelativeDifference(a.x_m, b.x_m), maxRelativeDifference(a.y_m, b.y_m),
                   maxRelativeDifference(a.fx_n, b.fx_n), maxRelativeDifference(a.fy_n, b.fy_n)});
}

double mean(const std::vector<double>& v, std::size_t from) {
  double sum = 0.0;
  for (std::size_t k = from; k < v.size(); ++k) sum += v[k];
  return sum / static_cast<double>(v.size() - from);
}

// A 4-flute 12 mm end mill, half immersion down-milling, modes well above the tooth-passing frequency.
MillingSetup fourFlute() {
  MillingSetup s = test::makeSetup(4, 0.012, 6e8, 0.3, {{1000.0, 0.03, 2.0e7}}, {{1100.0, 0.03, 2.2e7}},
                                   MillingDirection::Down, 0.5);
  return s;
}

SimulationOptions shortRun(int revolutions = 12, int evaluated = 4) {
  SimulationOptions o;
  o.revolutions = revolutions;
  o.evaluated_revolutions = evaluated;
  return o;
}

// The rigid tool's chip of tooth j by the static rule: max(0, min_k [s_t (n_t / 2 pi) A_jk sin phi + rho_j -
// rho_{j+k}]).
double staticChip(const MillingSetup& s, double feed, int j, double phi) {
  double chip = 1e300, turned = 0.0;
  for (int k = 1; k <= s.teeth; ++k) {
    turned += s.pitchRad((j + k - 1) % s.teeth);
    chip = std::min(chip,
                    feed * s.teeth / (2 * kPi) * turned * std::sin(phi) + s.runoutM(j) - s.runoutM((j + k) % s.teeth));
  }
  return std::max(0.0, chip);
}
}  // namespace

class TestCutterGeometrySimulation : public QObject {
  Q_OBJECT
 private slots:
  // A pitch list of equal pitches is the uniform cutter: the same result, bit for bit.
  void equalPitchesAreUniform() {
    const OperatingPoint p{5800.0 / 60.0, 0.4924e-3, 0.2722e-3};
    const MillingSetup uniform = test::rubioR1();
    MillingSetup listed = uniform;
    listed.pitch_rad.assign(3, 2 * kPi / 3);
    const SimulationResult a = simulateMilling(uniform, p, shortRun());
    const SimulationResult b = simulateMilling(listed, p, shortRun());
    QCOMPARE(b.trace.x_m, a.trace.x_m);
    QCOMPARE(b.trace.fy_n, a.trace.fy_n);
    QCOMPARE(b.indicators.eta, a.indicators.eta);
  }

  // Pitches 1e-7 rad apart take the general path (per-tooth passes, fractional delays read by Hermite
  // interpolation, a plan over a revolution), and stay within O(1e-7) of the uniform cutter.
  void nearlyEqualPitchesApproachUniform() {
    const OperatingPoint p{5800.0 / 60.0, 0.4924e-3, 0.2722e-3};
    const MillingSetup uniform = test::rubioR1();
    MillingSetup perturbed = uniform;
    perturbed.pitch_rad = {2 * kPi / 3 + 1e-7, 2 * kPi / 3 - 1e-7, 2 * kPi / 3};
    QVERIFY(!perturbed.uniformPitch());
    const SimulationResult a = simulateMilling(uniform, p, shortRun());
    const SimulationResult b = simulateMilling(perturbed, p, shortRun());
    const double difference = traceDifference(b.trace, a.trace);
    qInfo("pitch +-1e-7 rad: max relative trace difference %.3g", difference);
    QVERIFY2(difference < 1e-5, qPrintable(QString::number(difference)));
    QVERIFY(difference > 0.0);
  }

  // Zero helix: one slice is the straight tooth (bit for bit), four identical slices are the same to
  // round-off.
  void zeroHelixSlicesAreStraightTeeth() {
    const OperatingPoint p{5800.0 / 60.0, 0.4924e-3, 0.2722e-3};
    const MillingSetup s = test::rubioR1();
    SimulationOptions o = shortRun();
    const SimulationResult straight = simulateMilling(s, p, o);
    o.axial_slices = 1;
    const SimulationResult one = simulateMilling(s, p, o);
    QCOMPARE(one.trace.x_m, straight.trace.x_m);
    QCOMPARE(one.trace.fx_n, straight.trace.fx_n);
    o.axial_slices = 4;
    const SimulationResult four = simulateMilling(s, p, o);
    const double difference = traceDifference(four.trace, straight.trace);
    QVERIFY2(difference < 1e-12, qPrintable(QString::number(difference)));
  }

  // A rigid 4-flute slot cutter with runout (10, 0, -5, 0) um: the force at every sample is the static
  // rule's, the largest chip is s_t + max_j (rho_j - rho_{j+1}) = s_t + 10 um (tooth 0 at phi = 90 deg),
  // and the mean force over a revolution does not move while the peak grows by about 10 %: at every
  // angle the chips of all teeth (each the distance to the outermost surface left before it) add up to
  // the feed per revolution n_t s_t sin phi, with or without runout.
  void runoutChangesChipNotMeanForce() {
    MillingSetup s = test::makeSetup(4, 0.012, 6e8, 0.3, {}, {}, MillingDirection::Up, 1.0);
    const OperatingPoint p{6000.0 / 60.0, 1e-3, 0.1e-3};
    SimulationOptions o = shortRun(3, 1);
    o.steps_per_tooth_period = 64;
    o.regenerative_passes = 4;  // the surface of any tooth in the last revolution, as the static rule
    TimeDomainSimulator plain(s, p, o);
    plain.run();
    s.runout_m = {10e-6, 0.0, -5e-6, 0.0};
    TimeDomainSimulator runout(s, p, o);
    runout.run();

    QVERIFY(std::abs(runout.window().max_chip_m - (p.feed_per_tooth_m + 10e-6)) < 1e-12 * p.feed_per_tooth_m);
    QVERIFY(std::abs(runout.window().max_static_chip_m - (p.feed_per_tooth_m + 10e-6)) < 1e-12 * p.feed_per_tooth_m);
    QVERIFY(std::abs(plain.window().max_chip_m - p.feed_per_tooth_m) < 1e-12 * p.feed_per_tooth_m);

    const SimulationTrace& tr = runout.trace();
    double worst = 0.0, peak = 0.0;
    for (std::size_t k = 0; k < tr.size(); ++k) {
      const double theta = 2 * kPi * p.spindle_rev_per_s * tr.time_s[k] + 1e-9;
      double fx = 0.0, fy = 0.0;
      for (int j = 0; j < s.teeth; ++j) {
        const double phi = theta + s.toothAngleRad(j);
        const ToothForce f = toothForce(s, p.axial_depth_m, phi, staticChip(s, p.feed_per_tooth_m, j, phi));
        fx += f.fx_n;
        fy += f.fy_n;
      }
      worst = std::max({worst, std::abs(fx - tr.fx_n[k]), std::abs(fy - tr.fy_n[k])});
      peak = std::max(peak, std::hypot(fx, fy));
    }
    QVERIFY2(worst < 1e-8 * peak, qPrintable(QString("%1 N of %2 N").arg(worst).arg(peak)));  // phi + 1e-9 rad

    const std::size_t last_rev = tr.size() - static_cast<std::size_t>(64 * 4);
    const double fx0 = mean(plain.trace().fx_n, last_rev), fy0 = mean(plain.trace().fy_n, last_rev);
    const double fx1 = mean(tr.fx_n, last_rev), fy1 = mean(tr.fy_n, last_rev);
    const double mean_shift = std::hypot(fx1 - fx0, fy1 - fy0) / std::hypot(fx0, fy0);
    const double peak_growth = runout.window().max_force_n / plain.window().max_force_n - 1.0;
    qInfo("runout: mean force shift %.3g, peak force growth %.3g", mean_shift, peak_growth);
    QVERIFY2(mean_shift < 1e-12, qPrintable(QString::number(mean_shift)));
    QVERIFY(peak_growth > 0.05);
  }

  // A 30 deg helix over b = 3 mm of a 12 mm cutter lags 16.5 deg: the peak force at a stable point
  // converges as the slices are refined, the differences shrinking about fourfold per halving.
  void helixSlicesConverge() {
    MillingSetup s = fourFlute();
    s.helix_rad = 30 * kDeg;
    const OperatingPoint p{10000.0 / 60.0, 3e-3, 0.05e-3};
    bool stable = true;
    auto run = [&](int slices) {
      SimulationOptions o = shortRun(20, 5);
      o.axial_slices = slices;
      QElapsedTimer timer;
      timer.start();
      const SimulationResult r = simulateMilling(s, p, o);
      const double ms = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
      stable = stable && !r.indicators.chatter;
      double peak_x = 0.0;
      for (std::size_t k = r.trace.size() / 2; k < r.trace.size(); ++k)
        peak_x = std::max(peak_x, std::abs(r.trace.x_m[k]));
      qInfo("%3d slices: peak force %.6f N, peak x %.8g m, %.1f ms", simulationAxialSlices(s, p.axial_depth_m, slices),
            r.indicators.peak_force_n, peak_x, ms);
      return std::pair{r.indicators.peak_force_n, peak_x};
    };
    std::vector<std::pair<double, double>> runs;
    for (int slices : {1, 4, 8, 16, 32, 128}) runs.push_back(run(slices));
    const auto [force_ref, x_ref] = runs.back();
    // 4, 8, 16, 32 slices: the steps of the sampled peak force shrink; the peak displacement (smooth,
    // filtered by the structure) converges at second order (the midpoint rule over the slices).
    for (std::size_t i = 1; i + 2 <= 4; ++i) {
      const double coarse = std::abs(runs[i + 1].first - runs[i].first);
      const double fine = std::abs(runs[i + 2].first - runs[i + 1].first);
      QVERIFY2(fine < 0.5 * coarse, qPrintable(QString("peak force steps %1 then %2 N").arg(coarse).arg(fine)));
    }
    for (std::size_t i = 1; i + 1 <= 4; ++i) {
      const double coarse = std::abs(runs[i].second - x_ref), fine = std::abs(runs[i + 1].second - x_ref);
      QVERIFY2(fine < 0.35 * coarse, qPrintable(QString("peak x errors %1 then %2 m").arg(coarse).arg(fine)));
    }
    const auto [force_default, x_default] = run(0);
    QVERIFY(stable);
    qInfo("default: peak force within %.3g, peak x within %.3g of 128 slices", force_default / force_ref - 1.0,
          x_default / x_ref - 1.0);
    QVERIFY(std::abs(force_default / force_ref - 1.0) < 0.01);
    QVERIFY(std::abs(x_default / x_ref - 1.0) < 0.005);
  }

  // The general kernel (theta(t), delays by Newton, plans on the fly) at a constant speed reproduces the
  // tabulated one for a variable-pitch, helical cutter with runout.
  void kernelsAgreeOnRealCutter() {
    MillingSetup s = fourFlute();
    s.helix_rad = 30 * kDeg;
    s.pitch_rad = {80 * kDeg, 100 * kDeg, 80 * kDeg, 100 * kDeg};
    s.runout_m = {5e-6, -3e-6, 0.0, 2e-6};
    const OperatingPoint p{10000.0 / 60.0, 2e-3, 0.05e-3};
    SimulationOptions o = shortRun(6, 2);
    o.regenerative_passes = 2;
    TimeDomainSimulator tabulated(s, p, o);
    tabulated.run({}, TimeDomainSimulator::Kernel::ConstantSpeed);
    TimeDomainSimulator general(s, p, o);
    general.run({}, TimeDomainSimulator::Kernel::VariableSpeed);
    const double difference = traceDifference(general.trace(), tabulated.trace());
    QVERIFY2(difference < 1e-9, qPrintable(QString::number(difference)));
  }

  // Spindle speed variation with a variable-pitch cutter: a small variation stays close to the
  // constant speed, and a stable cut stays stable.
  void speedVariationWithVariablePitch() {
    MillingSetup s = fourFlute();
    s.pitch_rad = {80 * kDeg, 100 * kDeg, 80 * kDeg, 100 * kDeg};
    const OperatingPoint p{10000.0 / 60.0, 1e-3, 0.05e-3};
    SimulationOptions o = shortRun(10, 3);
    const SimulationResult constant = simulateMilling(s, p, o);
    o.ssv = {0.01, 1.0};
    const SimulationResult varied = simulateMilling(s, p, o);
    QVERIFY(!constant.indicators.chatter && !varied.indicators.chatter);
    const double change = std::abs(varied.indicators.peak_force_n / constant.indicators.peak_force_n - 1.0);
    QVERIFY2(change < 0.05, qPrintable(QString::number(change)));
  }

  // The CVODE reference takes the same geometry: trajectories agree to 1 % of their peak.
  void cvodeAgreesOnRealCutter() {
    MillingSetup s = fourFlute();
    s.helix_rad = 30 * kDeg;
    s.pitch_rad = {80 * kDeg, 100 * kDeg, 80 * kDeg, 100 * kDeg};
    s.runout_m = {5e-6, -3e-6, 0.0, 2e-6};
    const OperatingPoint p{10000.0 / 60.0, 2e-3, 0.05e-3};
    SimulationOptions o = shortRun(6, 2);
    o.axial_slices = 4;
    o.steps_per_tooth_period = 64;
    TimeDomainSimulator rk4(s, p, o);
    rk4.run();
    const SimulationTrace reference = simulateMillingCvode(s, p, 6, 1e-8, 64, 1, 4);
    QCOMPARE(reference.size(), rk4.trace().size());
    const double difference = traceDifference(rk4.trace(), reference);
    qInfo("CVODE against RK4: %.3g", difference);
    QVERIFY2(difference < 1e-2, qPrintable(QString::number(difference)));
  }

  // Variable pitch and runout repeat the cut only once a revolution: the spindle harmonics of a stable
  // cut are forced vibration, not chatter.
  void spindleHarmonicsAreForced() {
    MillingSetup s = fourFlute();
    s.pitch_rad = {70 * kDeg, 110 * kDeg, 70 * kDeg, 110 * kDeg};
    s.runout_m = {10e-6, 0.0, 0.0, 0.0};
    const OperatingPoint p{10000.0 / 60.0, 1e-3, 0.05e-3};
    const SimulationResult r = simulateMilling(s, p, shortRun(40, 20));
    QVERIFY(!r.indicators.chatter);
    const double n = p.spindle_rev_per_s;
    const double f = r.indicators.largest_nonharmonic_hz;
    if (f > 0.0) QVERIFY2(std::abs(f - std::round(f / n) * n) > 0.1 * n, qPrintable(QString::number(f)));
  }

  // Variable pitch against chatter (Altintas, Engin & Budak 1999): alternating pitches 90 -+ 15 deg put
  // the two delays' regenerative phases at f_c about 1150 Hz half a period apart (Delta P = pi N / f_c =
  // 31 deg at 12000 rpm). At b = 20 mm the uniform cutter chatters; the variable-pitch one is stable,
  // and its eta - referred to the revolution-synchronous force, since its forced vibration changes the
  // chip - stays 1. At b = 30 mm both chatter.
  void variablePitchSuppressesChatter() {
    const OperatingPoint p{12000.0 / 60.0, 20e-3, 0.05e-3};
    SimulationOptions o;
    o.regenerative_passes = 4;
    MillingSetup s = fourFlute();
    const SimulationResult uniform = simulateMilling(s, p, o);
    s.pitch_rad = {75 * kDeg, 105 * kDeg, 75 * kDeg, 105 * kDeg};
    const SimulationResult variable = simulateMilling(s, p, o);
    qInfo("b 20 mm: eta uniform %.3f (f_c %.0f Hz), variable pitch %.4f", uniform.indicators.eta,
          uniform.indicators.chatter_frequency_hz.value_or(0.0), variable.indicators.eta);
    QVERIFY(uniform.indicators.chatter && uniform.indicators.eta > 1.5);
    QVERIFY(!variable.indicators.chatter);
    QVERIFY(std::abs(variable.indicators.eta - 1.0) < 1e-3);
    QVERIFY(std::abs(variable.indicators.chip_ratio - 1.0) < 1e-3);
    const SimulationResult deep = simulateMilling(s, {p.spindle_rev_per_s, 30e-3, p.feed_per_tooth_m}, o);
    qInfo("b 30 mm: variable pitch eta %.3f, f_c %.0f Hz", deep.indicators.eta,
          deep.indicators.chatter_frequency_hz.value_or(0.0));
    QVERIFY(deep.indicators.chatter && deep.indicators.eta > 1.5);
    const double n = p.spindle_rev_per_s, fc = deep.indicators.chatter_frequency_hz.value_or(0.0);
    QVERIFY(std::abs(fc - std::round(fc / n) * n) > 0.05 * n);  // not a spindle harmonic
  }

  void rejectsBadGeometry() {
    const OperatingPoint p{10000.0 / 60.0, 1e-3, 0.05e-3};
    MillingSetup s = fourFlute();
    s.pitch_rad = {90 * kDeg, 90 * kDeg, 180 * kDeg};
    QVERIFY_THROWS_EXCEPTION(InvalidInput, simulateMilling(s, p, shortRun()));
    s = fourFlute();
    SimulationOptions o = shortRun();
    o.axial_slices = -1;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, simulateMilling(s, p, o));
    s.pitch_rad = {10 * kDeg, 170 * kDeg, 90 * kDeg, 90 * kDeg};  // 10 deg needs m >= 36
    QCOMPARE(minimumStepsPerToothPeriod(s), 36);
    o.axial_slices = 0;
    o.steps_per_tooth_period = 32;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, simulateMilling(s, p, o));
    QVERIFY(automaticStepsPerToothPeriod(s, p.spindle_rev_per_s) >= 36);
  }
};

MX_REGISTER_TEST(TestCutterGeometrySimulation)
#include "test_cutter_geometry_simulation.moc"
