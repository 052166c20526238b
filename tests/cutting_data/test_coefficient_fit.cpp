// Cutting coefficients from test cuts, the average-force method: the closed forms of slotting, the mean
// forces of the rigid-tool force model averaged numerically over a revolution (an independent method),
// the 95 % confidence intervals' coverage under noise, and bad input.
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

#include "core/invalid_input.h"
#include "cutting_data/coefficient_fit.h"
#include "model/cutting_force.h"
#include "support/test_constants.h"
#include "test_registry.h"

using namespace mx;

namespace {
using mx::test::kPi;

TestCutSetup slotting() {
  return {4, 16e-3, 2e-3, 1.0, MillingDirection::Down};
}

CuttingCoefficients aluminium() {  // the order of magnitude of a 7075 end-milling test
  return {796e6, 168e6, 222e6, 26.8e3, 27.8e3, 1.6e3};
}

// The rigid-tool model of cutting_force.h with its edge and axial forces, averaged over one revolution by
// the rectangle rule at 100 000 angles (the force jumps where a tooth leaves the cut: an error of O(1e-5)).
TestCut averagedStaticCut(const TestCutSetup& t, const CuttingCoefficients& k, double c) {
  MillingSetup s;
  s.teeth = t.teeth;
  s.diameter_m = t.diameter_m;
  s.tangential_coefficient_pa = k.Ktc_pa;
  s.radial_ratio = k.Krc_pa / k.Ktc_pa;
  s.axial_coefficient_pa = k.Kac_pa;
  s.tangential_edge_n_per_m = k.Kte_n_per_m;
  s.radial_edge_n_per_m = k.Kre_n_per_m;
  s.axial_edge_n_per_m = k.Kae_n_per_m;
  s.direction = t.direction;
  s.radial_depth_m = t.radial_ratio * t.diameter_m;
  s.immersion = Immersion::fromRadialDepth(s.radial_depth_m, s.diameter_m, s.direction);
  const OperatingPoint q{100.0, t.depth_m, c};
  const StaticCut cut(s, q);
  TestCut mean{c, 0.0, 0.0, 0.0};
  constexpr int kAngles = 100000;
  for (int i = 0; i < kAngles; ++i) {
    const StaticForce f = cut.at(2.0 * kPi * i / kAngles);
    mean.fx_n += f.fx_n / kAngles;
    mean.fy_n += f.fy_n / kAngles;
    mean.fz_n += f.fz_n / kAngles;
  }
  return mean;
}

double relative(double got, double want) {
  return std::abs(got / want - 1.0);
}
}  // namespace

class TestCoefficientFit : public QObject {
  Q_OBJECT
 private slots:
  // Altintas (2.5): Fx = -N a K_rc c / 4 - N a K_re / pi, Fy = N a K_tc c / 4 + N a K_te / pi,
  // Fz = N a K_ac c / pi + N a K_ae / 2 (our z along F_a).
  void slottingClosedForms() {
    const TestCutSetup t = slotting();
    const CuttingCoefficients k = aluminium();
    const double c = 0.1e-3, Na = t.teeth * t.depth_m;
    const TestCut f = meanCutForces(t, k, c);
    QVERIFY(relative(f.fx_n, -Na * k.Krc_pa * c / 4 - Na * k.Kre_n_per_m / kPi) < 1e-13);
    QVERIFY(relative(f.fy_n, Na * k.Ktc_pa * c / 4 + Na * k.Kte_n_per_m / kPi) < 1e-13);
    QVERIFY(relative(f.fz_n, Na * k.Kac_pa * c / kPi + Na * k.Kae_n_per_m / 2) < 1e-13);
  }

  // The rigid-tool force model, edge and axial forces included, averaged numerically, gives back all six
  // coefficients to 0.1 %; without edge forces the intercepts vanish.
  void recoversTheForceModelsCoefficients_data() {
    QTest::addColumn<double>("radial_ratio");
    QTest::addColumn<int>("direction");
    QTest::newRow("slotting") << 1.0 << int(MillingDirection::Down);
    QTest::newRow("half, down") << 0.5 << int(MillingDirection::Down);
    QTest::newRow("half, up") << 0.5 << int(MillingDirection::Up);
    QTest::newRow("quarter, down") << 0.25 << int(MillingDirection::Down);
    QTest::newRow("10 %, up") << 0.1 << int(MillingDirection::Up);
  }
  void recoversTheForceModelsCoefficients() {
    QFETCH(double, radial_ratio);
    QFETCH(int, direction);
    TestCutSetup t = slotting();
    t.radial_ratio = radial_ratio;
    t.direction = static_cast<MillingDirection>(direction);
    const std::vector<double> feeds{0.05e-3, 0.1e-3, 0.15e-3, 0.2e-3, 0.25e-3};
    const CuttingCoefficients k = aluminium();
    std::vector<TestCut> cuts;
    cuts.reserve(feeds.size());
    for (double c : feeds) cuts.push_back(averagedStaticCut(t, k, c));
    const CuttingCoefficients got = fitCuttingCoefficients(t, cuts).coefficients;
    const std::pair<double, double> pairs[] = {{got.Ktc_pa, k.Ktc_pa},           {got.Krc_pa, k.Krc_pa},
                                               {got.Kac_pa, k.Kac_pa},           {got.Kte_n_per_m, k.Kte_n_per_m},
                                               {got.Kre_n_per_m, k.Kre_n_per_m}, {got.Kae_n_per_m, k.Kae_n_per_m}};
    for (const auto& [value, truth] : pairs)
      QVERIFY2(relative(value, truth) < 1e-3, qPrintable(QString("%1 vs %2").arg(value).arg(truth)));

    const CuttingCoefficients plain{6e8, 1.8e8, 0.0, 0.0, 0.0, 0.0};
    cuts.clear();
    for (double c : feeds) cuts.push_back(averagedStaticCut(t, plain, c));
    const CoefficientFit fit = fitCuttingCoefficients(t, cuts);
    QVERIFY2(relative(fit.coefficients.Ktc_pa, 6e8) < 1e-3, qPrintable(QString::number(fit.coefficients.Ktc_pa)));
    QVERIFY2(relative(fit.Kr(), 0.3) < 1e-3, qPrintable(QString::number(fit.Kr())));
    // The intercepts vanish next to the forces of one feed step.
    const double scale = 6e8 * t.depth_m * 0.05e-3;
    QVERIFY(std::abs(fit.coefficients.Kte_n_per_m) * t.depth_m < 1e-6 * scale);
    QVERIFY(std::abs(fit.coefficients.Kre_n_per_m) * t.depth_m < 1e-6 * scale);
    QVERIFY(fit.lines[0].r2 > 1.0 - 1e-12 && fit.lines[1].r2 > 1.0 - 1e-12);
  }

  // All six coefficients from the model's own mean forces, edge forces included, at every immersion.
  void recoversAllSixExactly() {
    const CuttingCoefficients k = aluminium();
    for (double ratio : {1.0, 0.5, 0.2}) {
      TestCutSetup t = slotting();
      t.radial_ratio = ratio;
      std::vector<TestCut> cuts;
      for (double c : {0.04e-3, 0.08e-3, 0.12e-3, 0.16e-3}) cuts.push_back(meanCutForces(t, k, c));
      const CuttingCoefficients got = fitCuttingCoefficients(t, cuts).coefficients;
      QVERIFY(relative(got.Ktc_pa, k.Ktc_pa) < 1e-9 && relative(got.Krc_pa, k.Krc_pa) < 1e-9);
      QVERIFY(relative(got.Kac_pa, k.Kac_pa) < 1e-9);
      QVERIFY(relative(got.Kte_n_per_m, k.Kte_n_per_m) < 1e-9 && relative(got.Kre_n_per_m, k.Kre_n_per_m) < 1e-9);
      QVERIFY(relative(got.Kae_n_per_m, k.Kae_n_per_m) < 1e-9);
    }
  }

  // With 3 N of Gaussian noise on every mean force, the true coefficients lie inside the 95 % intervals in
  // about 95 % of 400 seeded experiments of 6 cuts (binomial: 0.92..0.98 holds with probability > 0.99).
  void confidenceIntervalsCoverTheTruth() {
    const TestCutSetup t = slotting();
    const CuttingCoefficients k = aluminium();
    std::mt19937 rng(2026);
    std::normal_distribution<double> noise(0.0, 3.0);
    int covered_kt = 0, covered_kte = 0, covered_kae = 0;
    constexpr int kTrials = 400;
    for (int trial = 0; trial < kTrials; ++trial) {
      std::vector<TestCut> cuts;
      for (double c : {0.05e-3, 0.08e-3, 0.11e-3, 0.14e-3, 0.17e-3, 0.2e-3}) {
        TestCut f = meanCutForces(t, k, c);
        f.fx_n += noise(rng), f.fy_n += noise(rng), f.fz_n += noise(rng);
        cuts.push_back(f);
      }
      const CoefficientFit fit = fitCuttingCoefficients(t, cuts);
      covered_kt += std::abs(fit.coefficients.Ktc_pa - k.Ktc_pa) <= fit.half_width_95.Ktc_pa;
      covered_kte += std::abs(fit.coefficients.Kte_n_per_m - k.Kte_n_per_m) <= fit.half_width_95.Kte_n_per_m;
      covered_kae += std::abs(fit.coefficients.Kae_n_per_m - k.Kae_n_per_m) <= fit.half_width_95.Kae_n_per_m;
    }
    for (int covered : {covered_kt, covered_kte, covered_kae}) {
      QVERIFY2(covered >= 0.92 * kTrials && covered <= 0.98 * kTrials, qPrintable(QString::number(covered)));
    }
  }

  void residualsAndR2() {
    const TestCutSetup t = slotting();
    std::vector<TestCut> cuts;
    for (double c : {0.1e-3, 0.2e-3, 0.3e-3}) cuts.push_back(meanCutForces(t, aluminium(), c));
    cuts[1].fy_n += 6.0;  // the middle cut 6 N high: the line moves 2 N up, residuals -2, +4, -2 N
    const CoefficientFit fit = fitCuttingCoefficients(t, cuts);
    QCOMPARE(fit.lines[1].residuals_n.size(), std::size_t(3));
    QVERIFY(std::abs(fit.lines[1].residuals_n[0] + 2.0) < 1e-9 && std::abs(fit.lines[1].residuals_n[1] - 4.0) < 1e-9);
    QVERIFY(fit.lines[1].r2 < 1.0 && fit.lines[1].r2 > 0.99);
    QCOMPARE(fit.lines[0].r2, 1.0);
  }

  void studentQuantiles() {
    QCOMPARE(studentT95(1), 12.706);
    QCOMPARE(studentT95(30), 2.042);
    QVERIFY(std::abs(studentT95(31) - 2.0395) < 5e-4);  // tables: 2.040 at 31
    QVERIFY(std::abs(studentT95(120) - 1.9799) < 5e-4);
    QVERIFY(std::abs(studentT95(100000) - 1.95998) < 1e-4);
    QVERIFY_THROWS_EXCEPTION(InvalidInput, studentT95(0));
  }

  void badInputNamesTheField_data() {
    QTest::addColumn<int>("teeth");
    QTest::addColumn<double>("ratio");
    QTest::addColumn<double>("feed2");
    QTest::addColumn<QString>("message");
    QTest::newRow("teeth") << 0 << 1.0 << 0.2e-3 << "teeth = 0";
    QTest::newRow("radial ratio") << 4 << 1.5 << 0.2e-3 << "radial_ratio = 1.5";
    QTest::newRow("feed") << 4 << 1.0 << -0.1e-3 << "test cut 2: feed per tooth";
    QTest::newRow("one feed") << 4 << 1.0 << 0.1e-3 << "at least 2 different feeds";
  }
  void badInputNamesTheField() {
    QFETCH(int, teeth);
    QFETCH(double, ratio);
    QFETCH(double, feed2);
    QFETCH(QString, message);
    TestCutSetup t = slotting();
    t.teeth = teeth;
    t.radial_ratio = ratio;
    const std::vector<TestCut> cuts{{0.1e-3, -10.0, 100.0, 5.0}, {feed2, -20.0, 200.0, 8.0}};
    try {
      fitCuttingCoefficients(t, cuts);
      QFAIL("accepted");
    } catch (const InvalidInput& e) {
      QVERIFY2(QString(e.what()).contains(message), e.what());
    }
  }
};

MX_REGISTER_TEST(TestCoefficientFit)
#include "test_coefficient_fit.moc"
