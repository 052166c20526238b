// Zeroth-order lobes of variable-pitch cutters (Altintas, Engin & Budak 1999): the general path against
// the uniform one, the single-mode closed form, an independent dense scan of the characteristic
// equation, and the design purpose (a raised limit near the speed the pitch is tuned for).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numbers>

#include "model/cutting_force.h"
#include "stability/zero_order_lobes.h"
#include "stability/zoa_variable_pitch.h"
#include "support/fixtures.h"
#include "support/speed_grids.h"
#include "support/test_constants.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::kDeg;
using cplx = std::complex<double>;
using mx::test::kPi;

using mx::test::minFinite;
using mx::test::rpmGrid;
MillingSetup withPitchDeg(MillingSetup s, const std::vector<double>& pitch_deg) {
  s.teeth = static_cast<int>(pitch_deg.size());
  s.pitch_rad.clear();
  for (double p : pitch_deg) s.pitch_rad.push_back(p * kDeg);
  return s;
}
MillingSetup equalPitches(MillingSetup s) {
  s.pitch_rad.assign(static_cast<size_t>(s.teeth), 2.0 * kPi / s.teeth);
  return s;
}
// The tool of the design test: the Insperger mode (x only, 922 Hz) on a 4-flute cutter, slotting.
MillingSetup fourFluteInsperger() {
  MillingSetup s = test::insperger(1.0);
  s.teeth = 4;
  return s;
}
// R1's two modes on a 4-flute cutter, slotting.
MillingSetup fourFluteR1() {
  MillingSetup s = test::rubioR1();
  s.teeth = 4;
  return s;
}

// det[I - (K_t b / 4 pi) S [A0][G]] written out for diagonal G, independently of the engine's eigenvalues.
cplx characteristicDeterminant(const MillingSetup& s, double speed, double depth, double w) {
  const cplx si{0.0, w};
  const DirectionalFactors a = averageDirectionalFactors(s.immersion, s.radial_ratio);
  const cplx k = s.tangential_coefficient_pa * depth / (4.0 * kPi) * regenerativePitchSum(s, speed, si);
  const cplx gx = receptance(s.modes_x, si), gy = receptance(s.modes_y, si);
  return (1.0 - k * a.xx * gx) * (1.0 - k * a.yy * gy) - k * k * a.xy * a.yx * gx * gy;
}

// Smallest positive real depth of det = 0 over a uniform chatter-frequency grid of `samples` points in
// [0.3 f_min, 3 f_max]: det is a quadratic in b with roots b1, b2; Im b1 * Im b2 does not depend on their
// order, so its sign changes locate a real root without following eigenvalue branches.
double denseScanLimit(const MillingSetup& s, double speed, int samples) {
  const DirectionalFactors a = averageDirectionalFactors(s.immersion, s.radial_ratio);
  double lo = 1e30, hi = 0.0;
  for (const ModalAxis* axis : {&s.modes_x, &s.modes_y})
    for (const Mode& m : *axis) lo = std::min(lo, m.angularFrequency()), hi = std::max(hi, m.angularFrequency());
  lo *= 0.3;
  hi *= 3.0;
  // Depth roots at w: det = 1 - k tr + k^2 d with k = K_t b S / 4 pi.
  auto depths = [&](double w, cplx out[2]) {
    const cplx si{0.0, w};
    const cplx gx = receptance(s.modes_x, si), gy = receptance(s.modes_y, si);
    const cplx tr = a.xx * gx + a.yy * gy, d = (a.xx * a.yy - a.xy * a.yx) * gx * gy;
    const cplx scale = 4.0 * kPi / (s.tangential_coefficient_pa * regenerativePitchSum(s, speed, si));
    if (std::abs(d) < 1e-12 * std::norm(tr)) {
      out[0] = scale / tr;
      return 1;
    }
    const cplx disc = std::sqrt(tr * tr - 4.0 * d);
    out[0] = scale * (tr - disc) / (2.0 * d);
    out[1] = scale * (tr + disc) / (2.0 * d);
    return 2;
  };
  auto indicator = [](const cplx b[2], int n) { return n == 1 ? b[0].imag() : b[0].imag() * b[1].imag(); };
  auto realest = [](const cplx b[2], int n) {
    return n == 1 || std::abs(b[0].imag()) < std::abs(b[1].imag()) ? b[0] : b[1];
  };
  double best = LobeDiagram::kNone;
  cplx b0[2], b1[2];
  int n0 = depths(lo, b0);
  for (int i = 1; i < samples; ++i) {
    const double w = lo + (hi - lo) * i / (samples - 1);
    const int n1 = depths(w, b1);
    const double f0 = indicator(b0, n0), f1 = indicator(b1, n1);
    if (n0 == n1 && ((f0 < 0.0 && f1 > 0.0) || (f0 > 0.0 && f1 < 0.0))) {
      const double t = f0 / (f0 - f1);
      // The root that turns real here has the smaller |Im| at both ends (whatever their order).
      const cplx left = realest(b0, n0), right = realest(b1, n1);
      const double re = left.real() + t * (right.real() - left.real());
      if (re > 0.0) best = std::min(best, re);
    }
    b0[0] = b1[0], b0[1] = b1[1], n0 = n1;
  }
  return best;
}
}  // namespace

class TestZoaVariablePitch : public QObject {
  Q_OBJECT
 private slots:
  // S(s) = sum_j (1 - e^{-s tau_j}): n (1 - e^{-s T}) for equal pitches; for pitches 70/110/70/110 deg,
  // 2 (1 - e^{-s 70 deg / Omega}) + 2 (1 - e^{-s 110 deg / Omega}).
  void pitchSumReducesByHand() {
    const double speed = 150.0, omega = 2.0 * kPi * speed;
    for (const cplx s : {cplx{0.0, 5800.0}, cplx{-30.0, 4100.0}}) {
      const MillingSetup uniform = equalPitches(fourFluteR1());
      const cplx expected_uniform = 4.0 * (1.0 - std::exp(-s * (0.5 * kPi / omega)));
      QCOMPARE_LE(std::abs(regenerativePitchSum(uniform, speed, s) - expected_uniform), 1e-12);
      const MillingSetup variable = withPitchDeg(test::rubioR1(), {70, 110, 70, 110});
      const cplx expected =
          2.0 * (1.0 - std::exp(-s * (70.0 * kDeg / omega))) + 2.0 * (1.0 - std::exp(-s * (110.0 * kDeg / omega)));
      QCOMPARE_LE(std::abs(regenerativePitchSum(variable, speed, s) - expected), 1e-12);
    }
  }

  // The general path on equal pitches against the uniform path. Every point of a uniform lobe curve solves
  // the same equation exactly, so the general envelope at its speed is at or below it, and equal where the
  // point is the lowest lobe (asserted to 1e-6). The uniform envelope interpolates linearly between curve
  // points, mostly above the convex lobes: measured, the general envelope is never more than 1e-4 above it
  // and within 0.5 % of it at 88-100 % of the speeds; the rest are steep flanks and lightly damped lobes
  // at high speed, where the uniform curve points lie tens of rpm apart (up to 2 % lower, and 14-30 % lower
  // at 13920-13940 rpm where the uniform curves miss the top of a lobe: Insperger mode, 4 teeth).
  void equalPitchesMatchUniformPath_data() {
    QTest::addColumn<int>("tool");
    QTest::addColumn<double>("delta");
    QTest::newRow("R1, 3 teeth") << 0 << 0.0;
    QTest::newRow("R1, 3 teeth, delta 40") << 0 << 40.0;
    QTest::newRow("Insperger, 4 teeth") << 1 << 0.0;
    QTest::newRow("R2, half immersion down") << 2 << 0.0;
  }
  void equalPitchesMatchUniformPath() {
    QFETCH(int, tool);
    QFETCH(double, delta);
    MillingSetup s = tool == 0 ? test::rubioR1() : tool == 1 ? fourFluteInsperger() : test::rubioR2();
    if (tool == 2) {
      s.direction = MillingDirection::Down;
      s.immersion = Immersion::fromRadialDepth(0.5 * s.diameter_m, s.diameter_m, s.direction);
    }
    const auto speeds = rpmGrid(3000, 25000, 20);
    ZoaOptions o;
    o.delta_per_s = delta;
    const LobeDiagram uniform = computeZoaLobes(s, speeds, o);
    const LobeDiagram general = computeZoaLobesAnyPitch(equalPitches(s), speeds, o);
    double worst_above = 0.0;
    int finite = 0, close = 0;
    for (size_t i = 0; i < speeds.size(); ++i) {
      const double b = general.envelope_depth_m[i], b_ref = uniform.envelope_depth_m[i];
      QCOMPARE(std::isinf(b), std::isinf(b_ref));
      if (std::isinf(b)) continue;
      worst_above = std::max(worst_above, b / b_ref - 1.0);
      ++finite;
      close += std::abs(b / b_ref - 1.0) < 0.005 ? 1 : 0;
    }
    // Lobe points (every 7th) inside the speed range, against the general path at their own speeds.
    std::vector<double> point_speeds, point_depths;
    for (const LobeCurve& c : uniform.lobes)
      for (size_t j = 0; j < c.speed_rev_per_s.size(); j += 7)
        if (c.speed_rev_per_s[j] > speeds.front() && c.speed_rev_per_s[j] < speeds.back() &&
            c.depth_m[j] < o.max_depth_m) {
          point_speeds.push_back(c.speed_rev_per_s[j]);
          point_depths.push_back(c.depth_m[j]);
        }
    ZoaOptions uncapped = o;
    uncapped.max_depth_m = 1.0;
    const LobeDiagram at_points = computeZoaLobesAnyPitch(equalPitches(s), point_speeds, uncapped);
    double worst_point_above = 0.0;
    int on_envelope = 0;
    for (size_t j = 0; j < point_speeds.size(); ++j) {
      const double ratio = at_points.envelope_depth_m[j] / point_depths[j];
      worst_point_above = std::max(worst_point_above, ratio - 1.0);
      on_envelope += std::abs(ratio - 1.0) < 1e-6 ? 1 : 0;
    }
    const double close_fraction = static_cast<double>(close) / finite;
    qInfo(
        "equal pitches: general above the uniform envelope by at most %.2g, within 0.5 %% at %.1f %% of %d "
        "speeds; %zu lobe points: general above by at most %.2g, %d equal within 1e-6",
        worst_above, close_fraction * 100, finite, point_speeds.size(), worst_point_above, on_envelope);
    QVERIFY(worst_above < 1e-4);
    QVERIFY(close_fraction > 0.85);
    QVERIFY(worst_point_above < 1e-6);
    QVERIFY(on_envelope >= static_cast<int>(point_speeds.size()) / 20);
  }

  // Hand-derived limit through the general path: one x mode, slotting, equal pitches: the lowest lobe is
  // 2 pi / (n_t K_t alpha_xx Re G_min) (singleModeMinimumDepth), within 0.5 %.
  void singleModeMinimumThroughGeneralPath() {
    const MillingSetup s = equalPitches(fourFluteInsperger());
    const double closed = singleModeMinimumDepth(s);
    const LobeDiagram d = computeZoaLobesAnyPitch(s, rpmGrid(5000, 25000, 10), {});
    const double found = minFinite(d.envelope_depth_m);
    qInfo("closed form %.6g m, general path %.6g m", closed, found);
    QVERIFY(std::abs(found / closed - 1.0) < 0.005);
  }

  // Pitches 70/110/70/110 deg, slotting: at each speed det[...] vanishes at the returned depth and chatter
  // frequency (measured below 1e-14), and the depth is the smallest real root of an independent dense scan
  // (400 000 frequencies; measured within 8e-8).
  void variablePitchRootIsTheDenseScanMinimum_data() {
    QTest::addColumn<int>("tool");
    QTest::newRow("R1 modes, 4 flutes") << 0;
    QTest::newRow("Insperger mode, 4 flutes") << 1;
  }
  void variablePitchRootIsTheDenseScanMinimum() {
    QFETCH(int, tool);
    const MillingSetup s = withPitchDeg(tool == 0 ? fourFluteR1() : fourFluteInsperger(), {70, 110, 70, 110});
    const auto speeds = rpmGrid(4000, 16000, 1500);
    const LobeDiagram d = computeZoaLobes(s, speeds, {});
    QVERIFY(d.lobes.empty());
    for (size_t i = 0; i < speeds.size(); ++i) {
      const double b = d.envelope_depth_m[i], w = 2.0 * kPi * d.envelope_chatter_hz[i];
      QVERIFY(std::isfinite(b));
      const double residual = std::abs(characteristicDeterminant(s, speeds[i], b, w));
      const double scan = denseScanLimit(s, speeds[i], 400000);
      qInfo("%.0f rpm: b %.5g mm at %.2f Hz, |det| %.2g, dense scan %.5g mm (%.3g)", speeds[i] * 60.0, b * 1e3,
            w / (2.0 * kPi), residual, scan * 1e3, b / scan - 1.0);
      QVERIFY(residual < 1e-12);
      QVERIFY(std::abs(b / scan - 1.0) < 1e-6);
    }
  }

  // The design purpose (Altintas, Engin & Budak 1999): for alternating pitches pi/2 -+ d the regenerative
  // terms e^{-s tau_1} + e^{-s tau_2} = 2 e^{-s T} cos(omega d / Omega) cancel where omega_c d / Omega =
  // pi / 2. The uniform 4-flute tool (Insperger mode) has a lobe minimum of 0.1491 mm at 7988 rpm,
  // 932.2 Hz; d = pi Omega / (2 omega_c) = 12.85 deg, so pitches 77/103 deg. Measured: at 7990 rpm the
  // limit rises from 0.149 mm to 2.10 mm, and over 7200-8800 rpm its minimum from 0.149 to 0.958 mm.
  void variablePitchRaisesTheLimitNearItsDesignSpeed() {
    const MillingSetup uniform = fourFluteInsperger();
    const MillingSetup variable = withPitchDeg(uniform, {77, 103, 77, 103});
    ZoaOptions o;
    o.max_depth_m = 1.0;
    const auto window = rpmGrid(7200, 8800, 10);
    const LobeDiagram u = computeZoaLobes(uniform, window, o);
    const LobeDiagram v = computeZoaLobes(variable, window, o);
    const size_t design = 79;  // 7990 rpm
    QCOMPARE(window[design] * 60.0, 7990.0);
    const double uniform_min = minFinite(u.envelope_depth_m), variable_min = minFinite(v.envelope_depth_m);
    qInfo("7990 rpm: uniform %.4g mm, variable %.4g mm; 7200-8800 rpm minimum: uniform %.4g mm, variable %.4g mm",
          u.envelope_depth_m[design] * 1e3, v.envelope_depth_m[design] * 1e3, uniform_min * 1e3, variable_min * 1e3);
    QVERIFY(std::abs(uniform_min / singleModeMinimumDepth(uniform) - 1.0) < 0.005);
    QVERIFY(v.envelope_depth_m[design] > 10.0 * u.envelope_depth_m[design]);
    QVERIFY(variable_min > 5.0 * uniform_min);
  }

  // The margin lowers the variable-pitch limit at every speed and the lowest one strictly (Rule 1.1); a
  // measured FRF sampled from the modes at 1 Hz gives the modal result within 1 % (as for uniform pitch,
  // stability.zoa_measured_frf).
  void marginAndMeasuredFrf() {
    const MillingSetup s = withPitchDeg(fourFluteR1(), {70, 110, 70, 110});
    const auto speeds = rpmGrid(3000, 15000, 50);
    const LobeDiagram nominal = computeZoaLobes(s, speeds, {});
    ZoaOptions o;
    o.delta_per_s = 40.0;
    const LobeDiagram margined = computeZoaLobes(s, speeds, o);
    for (size_t i = 0; i < speeds.size(); ++i)
      QVERIFY(margined.envelope_depth_m[i] <= nominal.envelope_depth_m[i] * (1.0 + 1e-9));
    QVERIFY(minFinite(margined.envelope_depth_m) < minFinite(nominal.envelope_depth_m));

    MillingSetup measured = s;
    measured.measured_x = test::sampledAxis(s.modes_x, 0.0, 4000.0, 1.0);
    measured.measured_y = test::sampledAxis(s.modes_y, 0.0, 4000.0, 1.0);
    measured.modes_x.clear();
    measured.modes_y.clear();
    ZoaOptions m;
    m.dynamics = DynamicsSource::Measured;
    const LobeDiagram from_frf = computeZoaLobes(measured, speeds, m);
    double worst = 0.0;
    for (size_t i = 0; i < speeds.size(); ++i)
      worst = std::max(worst, std::abs(from_frf.envelope_depth_m[i] / nominal.envelope_depth_m[i] - 1.0));
    qInfo("margin 40/s: lowest %.4g mm (nominal %.4g mm); measured FRF: worst %.3g",
          1e3 * minFinite(margined.envelope_depth_m), 1e3 * minFinite(nominal.envelope_depth_m), worst);
    QVERIFY(worst < 0.01);
  }

  void invalidPitchIsRefused() {
    MillingSetup s = withPitchDeg(test::rubioR1(), {70, 110, 70, 100});
    QVERIFY_THROWS_EXCEPTION(InvalidInput, computeZoaLobes(s, rpmGrid(3000, 6000, 100), {}));
    s = withPitchDeg(test::rubioR1(), {70, 110, 70, 110});
    s.teeth = 3;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, computeZoaLobes(s, rpmGrid(3000, 6000, 100), {}));
  }

  void rigidVariablePitchToolHasNoLobes() {
    MillingSetup s = withPitchDeg(test::rubioR1(), {70, 110, 70, 110});
    s.modes_x.clear();
    s.modes_y.clear();
    for (double b : computeZoaLobes(s, rpmGrid(3000, 6000, 100), {}).envelope_depth_m) QVERIFY(std::isinf(b));
  }

  void progressAndCancellation() {
    const MillingSetup s = withPitchDeg(fourFluteR1(), {70, 110, 70, 110});
    std::vector<double> fractions;
    JobControl progress;
    progress.progress = [&](double f) { fractions.push_back(f); };
    computeZoaLobes(s, rpmGrid(3000, 6000, 100), {}, progress);
    QCOMPARE(fractions.size(), size_t{31});
    QVERIFY(std::is_sorted(fractions.begin(), fractions.end()));
    QCOMPARE(fractions.back(), 1.0);
    std::atomic<bool> cancel{false};
    JobControl control;
    control.cancel = &cancel;
    control.progress = [&](double) { cancel = true; };
    QVERIFY_THROWS_EXCEPTION(Cancelled, computeZoaLobes(s, rpmGrid(3000, 6000, 100), {}, control));
  }

  // 200 speeds of a two-mode, 4-flute variable-pitch tool, with the margin (reported, loosely bounded).
  void twoHundredSpeedsTiming() {
    const MillingSetup s = withPitchDeg(fourFluteR1(), {70, 110, 70, 110});
    const auto speeds = SpeedGrid{3000.0 / 60.0, 22900.0 / 60.0, 100.0 / 60.0}.values();
    QCOMPARE(speeds.size(), size_t{200});
    ZoaOptions o;
    o.delta_per_s = 20.0;
    const auto start = std::chrono::steady_clock::now();
    const LobeDiagram d = computeZoaLobes(s, speeds, o);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    qInfo("200 speeds: %.1f ms, %zu minima", ms, d.minima.size());
    QVERIFY(!d.minima.empty());
    QVERIFY(ms < 20000.0);
  }
};

MX_REGISTER_TEST(TestZoaVariablePitch)
#include "test_zoa_variable_pitch.moc"
