// Static cutting forces, directional factors, power, torque and MRR (Rubio et al. 2006 eq. 2-5;
// Pareto paper eq. 8).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/cutting_force.h"
#include "support/fixtures.h"
#include "support/test_constants.h"
#include "test_registry.h"

using namespace mx;
using mx::test::kPi;

class TestCuttingForce : public QObject {
  Q_OBJECT
 private slots:
  // seed-reading.md: R1 at q* = (5800 rpm, 0.4924 mm, 0.2722 mm/tooth) peaks at about 730 W.
  // Full immersion, 3 teeth: max sum sin(phi_j) = 1, so P = pi D N/60 * K_t b s_t = 732.6 W.
  void rubioOptimumPeakPower() {
    const MillingSetup s = test::rubioR1();
    const OperatingPoint q{5800.0 / 60.0, 0.4924e-3, 0.2722e-3};
    const CutPerformance p = evaluateCut(s, q);
    const double expected = kPi * 0.030 * 5800.0 / 60.0 * 6e8 * 0.4924e-3 * 0.2722e-3;
    QCOMPARE_LE(std::abs(p.peak_power_w / expected - 1.0), 1e-4);
    QVERIFY(std::abs(p.peak_power_w - 730.0) < 5.0);
    QVERIFY(p.peak_power_w < 745.3);
    // MRR = a b s_t n_t N with a = D.
    QCOMPARE_LE(std::abs(p.mrr_m3_per_s - 0.030 * 0.4924e-3 * 0.2722e-3 * 3 * 5800.0 / 60.0), 1e-15);
    // Torque = (D/2) sum F_t at the peak.
    QCOMPARE_LE(std::abs(p.peak_torque_nm - p.peak_power_w / (2.0 * kPi * 5800.0 / 60.0)), 1e-9);
    // Mean power over a tooth period: n_t K_t b s_t v (1 - cos phi_ex ...)/(2 pi): full immersion -> 2/(2 pi) n_t.
    QCOMPARE_LE(std::abs(p.mean_power_w / (expected * 3.0 / kPi) - 1.0), 2e-3);
  }

  // Directional factors against their integrals evaluated numerically.
  void directionalFactorsMatchQuadrature_data() {
    QTest::addColumn<double>("entry");
    QTest::addColumn<double>("exit");
    QTest::addColumn<double>("kr");
    QTest::newRow("full") << 0.0 << kPi << 0.3;
    QTest::newRow("half up") << 0.0 << kPi / 2 << 0.07;
    QTest::newRow("5% down") << std::acos(2 * 0.05 - 1) << kPi << 1.0 / 3.0;
  }
  void directionalFactorsMatchQuadrature() {
    QFETCH(double, entry);
    QFETCH(double, exit);
    QFETCH(double, kr);
    const DirectionalFactors a = averageDirectionalFactors({entry, exit}, kr);
    // alpha_ij = 2 * integral over the immersion of the force-projection matrix (Budak & Altintas 1998).
    double xx = 0, xy = 0, yx = 0, yy = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      const double p = entry + (exit - entry) * (i + 0.5) / n, w = (exit - entry) / n;
      const double s = std::sin(p), c = std::cos(p);
      xx += -(c + kr * s) * s * 2 * w;
      xy += -(c + kr * s) * c * 2 * w;
      yx += (s - kr * c) * s * 2 * w;
      yy += (s - kr * c) * c * 2 * w;
    }
    QCOMPARE_LE(std::abs(a.xx - xx), 1e-8);
    QCOMPARE_LE(std::abs(a.xy - xy), 1e-8);
    QCOMPARE_LE(std::abs(a.yx - yx), 1e-8);
    QCOMPARE_LE(std::abs(a.yy - yy), 1e-8);
  }

  void toothForceProjection() {
    const MillingSetup s = test::rubioR1();
    const double phi = kPi / 3;
    const ToothForce f = toothForce(s, 1e-3, phi, 1e-4);
    const double ft = 6e8 * 1e-3 * 1e-4, fr = 0.3 * ft;
    QCOMPARE_LE(std::abs(f.tangential_n - ft), 1e-12);
    QCOMPARE_LE(std::abs(f.fx_n - (-ft * std::cos(phi) - fr * std::sin(phi))), 1e-12);
    QCOMPARE_LE(std::abs(f.fy_n - (ft * std::sin(phi) - fr * std::cos(phi))), 1e-12);
    QCOMPARE(toothForce(s, 1e-3, phi, -1e-5).tangential_n, 0.0);       // tool out of the cut
    QCOMPARE(toothForce(s, 1e-3, 1.5 * kPi, 1e-4).tangential_n, 0.0);  // outside the immersion
  }

  // Edge forces (Altintas 2000, eq. 2.22): F_t = b (K_t h + K_te), F_r = b (K_r K_t h + K_re), F_z = b (K_ac h +
  // K_ae) while the tooth cuts, nothing outside.
  void toothForceWithEdgeForces() {
    MillingSetup s = test::rubioR1();
    s.tangential_edge_n_per_m = 25e3;
    s.radial_edge_n_per_m = 30e3;
    s.axial_coefficient_pa = 2e8;
    s.axial_edge_n_per_m = 2e3;
    const double phi = kPi / 3, b = 1e-3, h = 1e-4;
    const ToothForce f = toothForce(s, b, phi, h);
    const double ft = b * (6e8 * h + 25e3), fr = b * (0.3 * 6e8 * h + 30e3);
    QCOMPARE_LE(std::abs(f.tangential_n / ft - 1.0), 1e-14);
    QCOMPARE_LE(std::abs(f.fx_n / (-ft * std::cos(phi) - fr * std::sin(phi)) - 1.0), 1e-14);
    QCOMPARE_LE(std::abs(f.fy_n / (ft * std::sin(phi) - fr * std::cos(phi)) - 1.0), 1e-14);
    QCOMPARE_LE(std::abs(f.fz_n / (b * (2e8 * h + 2e3)) - 1.0), 1e-14);
    QCOMPARE(toothForce(s, b, phi, -1e-6).fz_n, 0.0);  // out of the cut: no ploughing either
  }

  // Mean power of a slot with edge forces: v (n_t b / 2 pi) integral_0^pi (K_t s_t sin phi + K_te) dphi
  // = v n_t b (2 K_t s_t + pi K_te) / (2 pi); with K_ae alone the peak axial force is that of the most
  // edges cutting at once: 2 of 3 teeth in a slot.
  void edgeForcesAddToPowerAndTorque() {
    MillingSetup s = test::rubioR1();  // 3 teeth, slotting
    s.tangential_edge_n_per_m = 25e3;
    const OperatingPoint q{100.0, 1e-3, 1e-4};
    const CutPerformance p = evaluateCut(s, q);
    const double v = kPi * s.diameter_m * 100.0;
    const double mean = v * 3 * 1e-3 * (2.0 * 6e8 * 1e-4 + kPi * 25e3) / (2.0 * kPi);
    QCOMPARE_LE(std::abs(p.mean_power_w / mean - 1.0), 2e-3);  // sampled at 1440 angles per pitch
    QCOMPARE_LE(std::abs(p.peak_torque_nm - p.peak_power_w / (2.0 * kPi * 100.0)), 1e-9);
    s.tangential_edge_n_per_m = 0.0;
    const CutPerformance plain = evaluateCut(s, q);
    QVERIFY(p.peak_power_w > plain.peak_power_w * 1.2);  // the edge adds 25e3 / (6e8 1e-4) = 42 % per tooth
    QCOMPARE(plain.peak_axial_force_n, 0.0);
    s.axial_edge_n_per_m = 2e3;
    // At any instant one or two of the 3 teeth cut the slot: the peak axial force is that of two edges.
    QCOMPARE_LE(std::abs(evaluateCut(s, q).peak_axial_force_n / (2.0 * 1e-3 * 2e3) - 1.0), 1e-12);
  }

  void immersionAngles_data() {
    QTest::addColumn<int>("direction");
    QTest::addColumn<double>("ratio");
    QTest::addColumn<double>("entry");
    QTest::addColumn<double>("exit");
    QTest::newRow("up full") << 0 << 1.0 << 0.0 << kPi;
    QTest::newRow("up half") << 0 << 0.5 << 0.0 << kPi / 2;
    QTest::newRow("down half") << 1 << 0.5 << kPi / 2 << kPi;
    QTest::newRow("down 5%") << 1 << 0.05 << std::acos(-0.9) << kPi;
    QTest::newRow("up 5%") << 0 << 0.05 << 0.0 << std::acos(0.9);
  }
  void immersionAngles() {
    QFETCH(int, direction);
    QFETCH(double, ratio);
    QFETCH(double, entry);
    QFETCH(double, exit);
    const Immersion im =
        Immersion::fromRadialDepth(ratio * 0.02, 0.02, direction == 0 ? MillingDirection::Up : MillingDirection::Down);
    QCOMPARE_LE(std::abs(im.entry_rad - entry), 1e-12);
    QCOMPARE_LE(std::abs(im.exit_rad - exit), 1e-12);
  }

  // One tooth slotting: the resultant K_t b s_t sin(phi) sqrt(1 + K_r^2) peaks at phi = 90 deg, so the
  // peak force per (b s_t) is K_t sqrt(1 + K_r^2) exactly (the sampling contains 90 deg).
  void peakForceOfOneToothIsAnalytic() {
    MillingSetup s = test::rubioR1();
    s.teeth = 1;
    QCOMPARE_LE(std::abs(peakPerDepthFeed(s, 1e-3, 1e-4).force_n / (6e8 * std::sqrt(1.0 + 0.3 * 0.3)) - 1.0), 1e-12);
  }

  // R1 (3 teeth, slotting): the peak resultant per (b s_t) against a fine sweep of the summed tooth
  // forces written out here, and linear in b s_t.
  void peakForceMatchesASweepAndScales() {
    const MillingSetup s = test::rubioR1();
    double swept = 0.0;
    for (int i = 0; i < 360000; ++i) {
      const double theta = 2.0 * kPi / 3.0 * i / 360000.0;
      double fx = 0.0, fy = 0.0;
      for (int j = 0; j < 3; ++j) {
        const double phi = theta + j * 2.0 * kPi / 3.0;
        if (phi > kPi) continue;
        const double ft = 6e8 * std::sin(phi), fr = 0.3 * ft;
        fx += -ft * std::cos(phi) - fr * std::sin(phi);
        fy += ft * std::sin(phi) - fr * std::cos(phi);
      }
      swept = std::max(swept, std::hypot(fx, fy));
    }
    QCOMPARE_LE(std::abs(peakPerDepthFeed(s, 1e-3, 1e-4).force_n / swept - 1.0), 1e-5);
    const CutPerformance p = evaluateCut(s, {80.0, 0.5e-3, 0.2e-3});
    QCOMPARE_LE(std::abs(p.peak_force_n / (peakPerDepthFeed(s, 1e-3, 1e-4).force_n * 0.5e-3 * 0.2e-3) - 1.0), 1e-12);
  }

  // Runout (Kline & DeVor): 2 teeth in half immersion, tooth 1 sticking out 10 um. It cuts what tooth 0
  // left, so its chip is s_t sin(phi) + 10 um; the peak tangential force is K_t b (s_t + 10 um) at 90 deg.
  // The mean power stays that of the true tool (the same material is removed) while every tooth cuts.
  void runoutChangesTheChipNotTheMean() {
    MillingSetup s = test::rubioR2();
    s.radial_depth_m = 0.5 * s.diameter_m;
    s.immersion = Immersion::fromRadialDepth(s.radial_depth_m, s.diameter_m, MillingDirection::Up);
    const OperatingPoint q{100.0, 1e-3, 0.1e-3};
    const CutPerformance plain = evaluateCut(s, q);
    s.runout_m = {0.0, 10e-6};
    const CutPerformance runout = evaluateCut(s, q);
    const double v = kPi * s.diameter_m * q.spindle_rev_per_s;
    QCOMPARE_LE(std::abs(runout.peak_power_w / (v * 6e8 * 1e-3 * 0.11e-3) - 1.0), 1e-9);
    QCOMPARE_LE(std::abs(plain.peak_power_w / (v * 6e8 * 1e-3 * 0.1e-3) - 1.0), 1e-9);
    QCOMPARE_LE(std::abs(runout.mean_power_w / plain.mean_power_w - 1.0), 2e-3);
    QCOMPARE_LE(std::abs(runout.mrr_m3_per_s - plain.mrr_m3_per_s), 1e-18);
  }

  // Variable pitch 160/200 deg on 2 teeth in half immersion (one tooth in cut at a time): tooth j's feed is
  // s_t n p_j / 2 pi, so the peak chip is s_t 2 * 200/360 and the peak is taken over a revolution.
  void variablePitchSharesTheFeedByPitch() {
    MillingSetup s = test::rubioR2();
    s.radial_depth_m = 0.5 * s.diameter_m;
    s.immersion = Immersion::fromRadialDepth(s.radial_depth_m, s.diameter_m, MillingDirection::Up);
    s.pitch_rad = {160.0 * kPi / 180.0, 200.0 * kPi / 180.0};
    const OperatingPoint q{100.0, 1e-3, 0.1e-3};
    const CutPerformance p = evaluateCut(s, q);
    const double v = kPi * s.diameter_m * q.spindle_rev_per_s;
    QCOMPARE_LE(std::abs(p.peak_power_w / (v * 6e8 * 1e-3 * 0.1e-3 * 400.0 / 360.0) - 1.0), 1e-9);
    MillingSetup equal = test::rubioR2();
    equal.pitch_rad = {kPi, kPi};
    const CutPerformance a = evaluateCut(equal, q), b = evaluateCut(test::rubioR2(), q);
    QCOMPARE(a.peak_power_w, b.peak_power_w);
    QCOMPARE(a.peak_force_n, b.peak_force_n);
  }

  // A 30 deg helix (R2, 2 teeth, a/D = 0.5 up, b = 5 mm: 26 deg of lag) spreads each edge's exit at
  // 90 deg over the depth: the peak resultant falls and the mean power stays. The default slicing (1 deg
  // per slice) is within 0.2 % of four times as many slices (measured 0.15 %).
  void helixSlicesSmoothThePeak() {
    MillingSetup s = test::rubioR2();
    s.radial_depth_m = 0.5 * s.diameter_m;
    s.immersion = Immersion::fromRadialDepth(s.radial_depth_m, s.diameter_m, MillingDirection::Up);
    const OperatingPoint q{100.0, 5e-3, 0.1e-3};
    const CutPerformance straight = evaluateCut(s, q);
    s.helix_rad = 30.0 * kPi / 180.0;
    const CutPerformance helical = evaluateCut(s, q);
    const int slices = defaultAxialSlices(s, q.axial_depth_m);
    QCOMPARE(slices, 27);
    double fine = 0.0;
    const StaticCut cut(s, q, 4 * slices);
    for (int i = 0; i < 1440; ++i) fine = std::max(fine, cut.at(kPi * i / 1440).resultant());
    QCOMPARE_LE(std::abs(helical.peak_force_n / fine - 1.0), 2e-3);
    qInfo("peak resultant: straight %.2f N, 30 deg helix %.2f N", straight.peak_force_n, helical.peak_force_n);
    QCOMPARE_LE(helical.peak_force_n, 0.97 * straight.peak_force_n);  // measured 288.4 N against 300.7 N
    QCOMPARE_LE(std::abs(helical.mean_power_w / straight.mean_power_w - 1.0), 2e-3);  // sampled: 0.11 %
  }

  void powerScalesWithDepthAndFeed() {
    const MillingSetup s = test::rubioR2();
    const double per_unit = 100.0 * peakPerDepthFeed(s, 1e-3, 1e-4).power_w_per_rev_per_s;
    const CutPerformance p = evaluateCut(s, {100.0, 2e-3, 5e-5});
    QCOMPARE_LE(std::abs(p.peak_power_w / (per_unit * 2e-3 * 5e-5) - 1.0), 1e-12);
  }
};

MX_REGISTER_TEST(TestCuttingForce)
#include "test_cutting_force.moc"
