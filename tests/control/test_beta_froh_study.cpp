// The beta-FROH study (2006 paper, section 4): the zero threshold against the paper's -0.6 and the first-order
// formula for each tau_c, its monotony in tau_c, the tau_c calibrated to -0.6, and where J_c(beta) of eq. 34 has
// its minimum under both readings (the paper's figure 13: near -0.3; not reproduced).
#include <atomic>
#include <cmath>

#include "control/beta_froh_study.h"
#include "core/cancellation.h"
#include "core/invalid_input.h"
#include "test_registry.h"

using namespace mx;

namespace {

const double kT = 60.0 / 715.0;  // one spindle period at 715 rpm

// One beta per tau_c: the thresholds need no J_c sweep.
BetaFrohStudyResult thresholdsOnly(std::vector<double> taus = {}) {
  BetaFrohStudySettings study;
  study.tau_c_s = std::move(taus);
  study.sweep = {0.0, 0.0, 0.1, 0};
  return betaFrohStudy(AdaptiveControlSettings{}, study);
}

}  // namespace

class TestBetaFrohStudy : public QObject {
  Q_OBJECT
  BetaFrohStudyResult full_;  // the default study: 9 tau_c x 41 betas

 private slots:
  void initTestCase() { full_ = betaFrohStudy(AdaptiveControlSettings{}, BetaFrohStudySettings{}); }

  // The paper: "a unstable zero of discretization when the beta-FROH takes beta < -0.6 values". With
  // tau_c = T/6 our threshold is -0.5991: the paper's value within 0.01.
  void thresholdAtTauCOverSixIsThePapers() {
    const BetaFrohStudyResult r = thresholdsOnly({kT / 6.0});
    QVERIFY(r.rows.front().threshold_found);
    QVERIFY2(std::abs(r.rows.front().threshold_beta - (-0.6)) <= 0.01,
             qPrintable(QString::number(r.rows.front().threshold_beta, 'g', 10)));
    QVERIFY(r.rows.front().threshold_near_paper);
  }

  // Our default tau_c = T/8 (half a tooth period, not calibrated) gives -0.572: the paper's -0.6 at the one
  // decimal it is printed with (tolerance 0.05); every tau_c in [7.53, 20.77] ms (T/11.1 ... T/4.04) does.
  void defaultThresholdRoundsToThePapers() {
    const BetaFrohStudyResult r = thresholdsOnly({kT / 8.0});
    QCOMPARE_LE(std::abs(r.default_tau_c_s - kT / 8.0), 1e-15);
    QCOMPARE_LE(std::abs(r.rows.front().threshold_beta - (-0.571987)), 1e-5);
    QCOMPARE_LE(std::abs(r.rows.front().threshold_beta - (-0.6)), 0.05);
    QCOMPARE_LE(std::abs(r.tau_c_near_paper_threshold_lo_s - 7.530e-3), 1e-5);
    QCOMPARE_LE(std::abs(r.tau_c_near_paper_threshold_hi_s - 20.773e-3), 1e-5);
    QVERIFY(r.tau_c_near_paper_threshold_lo_s < kT / 8.0 && kT / 8.0 < r.tau_c_near_paper_threshold_hi_s);
  }

  // The tau_c calibrated to -0.6 exactly: 14.107 ms = T/5.95; its threshold is -0.6 to the bisection's accuracy.
  void tauCCalibratedToThePapersThreshold() {
    const BetaFrohStudyResult r = thresholdsOnly({kT / 6.0});
    QCOMPARE_LE(std::abs(r.tau_c_at_paper_threshold_s - 14.1066e-3), 1e-6);
    AdaptiveControlSettings s;
    s.process.process_time_constant_s = r.tau_c_at_paper_threshold_s;
    QCOMPARE_LE(std::abs(closedLoopZeroThreshold(s) - (-0.6)), 1e-9);
  }

  // Analytic: with the drive neglected the threshold is -(1-a)/(2(1-c)); the 0.1 ms drive lowers it by less than
  // 2.5e-3 at every tau_c of the study (8e-4 at T/8, 1.9e-3 at 2T).
  void firstOrderFormulaAtEveryTauC() {
    const BetaFrohStudyResult r = thresholdsOnly();
    QCOMPARE(static_cast<int>(r.rows.size()), 9);
    for (const BetaFrohStudyRow& row : r.rows) {
      const double a = std::exp(-kT / row.tau_c_s), c = row.tau_c_s * (1.0 - a) / kT;
      const double formula = -(1.0 - a) / (2.0 * (1.0 - c));
      QCOMPARE_LE(std::abs(row.first_order_threshold_beta - formula), 1e-15);
      QVERIFY(row.threshold_found);
      QVERIFY2(row.threshold_beta < formula && formula - row.threshold_beta < 2.5e-3,
               qPrintable(QString("tau_c/T %1: %2 vs %3").arg(row.tau_c_over_T).arg(row.threshold_beta).arg(formula)));
    }
  }

  // Invariant: the threshold falls strictly with tau_c, inside (-1, -1/2) (the formula's limits).
  void thresholdFallsWithTauC() {
    const BetaFrohStudyResult r = thresholdsOnly();
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
      QVERIFY(r.rows[i].threshold_beta > -1.0 && r.rows[i].threshold_beta < -0.5);
      if (i > 0) {
        QVERIFY(r.rows[i].tau_c_s > r.rows[i - 1].tau_c_s);
        QVERIFY(r.rows[i].threshold_beta < r.rows[i - 1].threshold_beta);
      }
    }
  }

  // Figure 13 ("for a beta about -0.3, the value of the cost function is minimum") is not reproduced. At the
  // default tau_c = T/8 on the 0.05 grid both readings of eq. 34 have their minimum at beta = 0.70 (73.5 and
  // 880.5 N s, within 2 %).
  void defaultArgmins() {
    const BetaFrohStudyRow& row = full_.rows[1];
    QCOMPARE_LE(std::abs(row.tau_c_over_T - 0.125), 1e-12);
    QCOMPARE(static_cast<int>(full_.beta.size()), 41);
    const BetaFrohReadingResult &plant = row.readings[0], &model = row.readings[1];
    QCOMPARE(plant.reading, JcReading::PlantSamples);
    QCOMPARE(model.reading, JcReading::ReferenceModel);
    QVERIFY(plant.found && model.found);
    QCOMPARE_LE(std::abs(plant.best_beta - 0.70), 1e-9);
    QCOMPARE_LE(std::abs(plant.best_Jc_N_s - 73.48), 0.02 * 73.48);
    QCOMPARE_LE(std::abs(model.best_beta - 0.70), 1e-9);
    QCOMPARE_LE(std::abs(model.best_Jc_N_s - 880.5), 0.02 * 880.5);
    QVERIFY(!plant.near_paper && !model.near_paper);
    // the plant-samples reading is sweepBeta's J_c, argmin and all
    const BetaSweepResult sweep = sweepBeta(AdaptiveControlSettings{}, BetaFrohStudySettings{}.sweep);
    QCOMPARE(plant.Jc_N_s, sweep.Jc_N_s);
    QCOMPARE(model.Jc_N_s, sweep.Jc_model_N_s);
    QCOMPARE(plant.best_beta, sweep.best_beta);
  }

  // Over T/16 ... 2T no (tau_c, reading) lands near the paper: the ripple reading's minimum stays in [0.55, 1]
  // (it falls almost monotonically with beta), and the thresholds near -0.6 (T/8, T/6, T/5) go with minima far from
  // -0.3 under both readings.
  void noDefaultTauCMatchesThePaper() {
    QVERIFY(full_.matches.empty());
    QCOMPARE(static_cast<int>(full_.rows.size()), 9);
    for (const BetaFrohStudyRow& row : full_.rows) {
      QVERIFY(row.readings[0].found);
      QVERIFY2(row.readings[0].best_beta >= 0.55 - 1e-9, qPrintable(QString::number(row.readings[0].best_beta)));
      for (std::size_t i = 0; i < full_.beta.size(); ++i)
        QCOMPARE(static_cast<bool>(row.unstable_zero[i]), full_.beta[i] < row.threshold_beta);
    }
  }

  // The only formal match of the fine tau_c scan (7.5 ... 21 ms by 0.5): the reference-model reading at
  // tau_c = 19 ms (T/4.4, threshold -0.637) has its minimum at -0.35, a one-point dip (911 N s between 1157 and
  // 1035; -0.60 gives 926), so not the basin of figure 13.
  void theFormalMatchIsAnIsolatedDip() {
    BetaFrohStudySettings study;
    study.tau_c_s = {19e-3};
    const BetaFrohStudyResult r = betaFrohStudy(AdaptiveControlSettings{}, study);
    const BetaFrohStudyRow& row = r.rows.front();
    QVERIFY(row.threshold_near_paper);
    QCOMPARE_LE(std::abs(row.threshold_beta - (-0.6372)), 1e-4);
    const BetaFrohReadingResult& model = row.readings[1];
    QCOMPARE_LE(std::abs(model.best_beta - (-0.35)), 1e-9);
    QVERIFY(model.near_paper);
    QVERIFY(model.isolated_minimum);
    QCOMPARE(static_cast<int>(r.matches.size()), 1);
    QCOMPARE(r.matches.front().reading, JcReading::ReferenceModel);
    QVERIFY(r.matches.front().isolated_minimum);
    QVERIFY(!row.readings[0].near_paper);
    QVERIFY(!row.readings[0].isolated_minimum);
  }

  void cancellation() {
    std::atomic<bool> cancel{true};
    JobControl job;
    job.cancel = &cancel;
    QVERIFY_THROWS_EXCEPTION(Cancelled, betaFrohStudy(AdaptiveControlSettings{}, BetaFrohStudySettings{}, job));
  }

  void progressCoversTheStudy() {
    BetaFrohStudySettings study;
    study.tau_c_s = {kT / 8.0, kT / 4.0};
    study.sweep = {0.0, 0.2, 0.1, 1};
    double last = 0.0;
    bool monotone = true;
    JobControl job;
    job.progress = [&](double f) {
      monotone = monotone && f >= last - 1e-12;
      last = f;
    };
    betaFrohStudy(AdaptiveControlSettings{}, study, job);
    QVERIFY(monotone);
    QCOMPARE_LE(std::abs(last - 1.0), 1e-12);
  }

  void invalid() {
    BetaFrohStudySettings study;
    study.tau_c_s = {0.0};
    QVERIFY_THROWS_EXCEPTION(InvalidInput, betaFrohStudy(AdaptiveControlSettings{}, study));
    study.tau_c_s = {std::nan("")};
    QVERIFY_THROWS_EXCEPTION(InvalidInput, betaFrohStudy(AdaptiveControlSettings{}, study));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, tauCForZeroThreshold(AdaptiveControlSettings{}, -0.4));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, tauCForZeroThreshold(AdaptiveControlSettings{}, -1.0));
  }
};

MX_REGISTER_TEST(TestBetaFrohStudy)
#include "test_beta_froh_study.moc"
