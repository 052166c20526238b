// The expert system on the 2006 example (section 3.D): Rule 4 selects R1 over the simplex, q* on the
// power limit at 5800 rpm, Rule 5 from cached simulations, Rule 6 keeps the weights on the simplex,
// and the invariants of the ranking (admissible points, MRR monotone in c2).
#include <atomic>
#include <cmath>
#include <limits>

#include "core/invalid_input.h"
#include "expert/expert_session.h"
#include "expert_fixtures.h"
#include "model/cutting_force.h"
#include "test_registry.h"

using namespace mx;

namespace {
using test::kR1;
using test::kR2;
}  // namespace

class TestExpertSession : public QObject {
  Q_OBJECT
 private slots:
  // c = (0.2, 0.725, 0.075): R1, q* = (5800 rpm, 0.5048 mm, 0.27 mm) on the power limit.
  // Paper: q* = (5800, 0.4924, 0.2722); the cost is flat along b s_t = const on the power limit.
  // The build polls the cancel flag (a cancelled build throws before any grid is done) and reports
  // the fraction of tools built, rising to 1.
  void buildIsCancellableAndReportsProgress() {
    std::atomic<bool> cancel{true};
    QVERIFY_THROWS_EXCEPTION(Cancelled, ExpertSession({test::rubioR1(), test::rubioR2()}, test::rubioExpertSettings(),
                                                      {}, JobControl{&cancel, {}}));
    std::vector<double> fractions;
    JobControl job;
    job.progress = [&](double f) { fractions.push_back(f); };
    const ExpertSession session({test::rubioR1(), test::rubioR2()}, test::rubioExpertSettings(), {}, job);
    QCOMPARE(fractions, (std::vector<double>{0.5, 1.0}));
    QCOMPARE(session.toolCount(), std::size_t(2));
  }

  void paperWeightsQStar() {
    const Ranking r = test::rubioSession().rank({0.2, 0.725, 0.075});
    QCOMPARE(r.tools.size(), std::size_t(2));
    QCOMPARE(r.selected().tool, kR1);
    const ExpertPoint q = r.selected().q;
    qInfo("q* = (%.3f rpm, %.4f mm, %.4f mm), P = %.2f W, dNs = %.1f rpm, C = %.5f", q.speed_rev_per_s * 60,
          q.depth_m * 1e3, q.feed_per_tooth_m * 1e3, q.power_w, q.speed_security * 60, r.selected().min_cost);
    QCOMPARE_LE(std::abs(q.speed_rev_per_s * 60.0 - 5800.0), 1e-6);
    QVERIFY(q.power_w <= 745.3);
    QVERIFY(q.power_w >= 0.98 * 745.3);  // on the power limit within 2 %
    const double bs_paper = 0.4924 * 0.2722, bs = q.depth_m * q.feed_per_tooth_m * 1e6;
    QCOMPARE_LE(std::abs(bs / bs_paper - 1.0), 0.02);
    QCOMPARE_LE(std::abs(q.speed_security * 60.0 - 1014.0), 5.0);  // 5800 - 4786 (left lobe minimum)
    QCOMPARE(r.tools[1].tool, kR2);
    QVERIFY(r.tools[1].min_cost > 5.0 * r.selected().min_cost);
  }

  // Figure 4: c3 = 0.075, c2 = 1 - c1 - c3: R1 has the lower minimum cost for every c1.
  void figure4() {
    for (int i = 0; i <= 37; ++i) {
      const double c1 = 0.025 * i;
      const std::vector<double> costs = test::rubioSession().minimumCosts({c1, 0.925 - c1, 0.075});
      QVERIFY2(costs[kR1] < costs[kR2], qPrintable(QString("c1 = %1").arg(c1)));
    }
  }

  // Figure 5: R1 over the simplex (step 0.05, 231 points) except the power-only corner c = (1, 0, 0),
  // where C = P / P_av and the lightest cut of the small R2 wins (see docs/fidelity.md).
  void figure5() {
    int r1 = 0, r2 = 0;
    for (int i = 0; i <= 20; ++i) {
      for (int j = 0; i + j <= 20; ++j) {
        const std::array<double, 3> c{0.05 * i, 0.05 * j, std::max(0.0, 1.0 - 0.05 * i - 0.05 * j)};
        const std::size_t selected = test::rubioSession().rank(c).selected().tool;
        if (i == 20) {
          QCOMPARE(selected, kR2);
          ++r2;
        } else {
          QVERIFY2(selected == kR1, qPrintable(QString("c = (%1, %2, %3)").arg(c[0]).arg(c[1]).arg(c[2])));
          ++r1;
        }
      }
    }
    QCOMPARE(r1, 230);
    QCOMPARE(r2, 1);
  }

  // Every ranked point (q* of every tool, and the best 12 points of R1) is admissible.
  void rankedPointsAdmissible_data() {
    QTest::addColumn<double>("c1");
    QTest::addColumn<double>("c2");
    QTest::newRow("paper") << 0.2 << 0.725;
    QTest::newRow("power") << 0.9 << 0.05;
    QTest::newRow("mrr") << 0.0 << 1.0;
    QTest::newRow("security") << 0.0 << 0.0;
    QTest::newRow("centre") << 1.0 / 3.0 << 1.0 / 3.0;
  }
  void rankedPointsAdmissible() {
    QFETCH(double, c1);
    QFETCH(double, c2);
    const std::array<double, 3> c{c1, c2, 1.0 - c1 - c2};
    const Ranking r = test::rubioSession().rank(c);
    for (const ToolChoice& t : r.tools) {
      QVERIFY(test::rubioSession().grid(t.tool).isAdmissible(t.q.speed_rev_per_s, t.q.depth_m, t.q.feed_per_tooth_m));
      QVERIFY(t.q.speed_security > 0.0);
    }
    const std::vector<ToolChoice> best = test::rubioSession().bestPoints(kR1, c, 12);
    QCOMPARE(best.size(), std::size_t(12));
    QCOMPARE(best.front().min_cost, r.tools.front().min_cost);
    for (std::size_t i = 0; i < best.size(); ++i) {
      QVERIFY(test::rubioSession().grid(kR1).isAdmissible(best[i].q.speed_rev_per_s, best[i].q.depth_m,
                                                          best[i].q.feed_per_tooth_m));
      if (i > 0) QVERIFY(best[i - 1].min_cost <= best[i].min_cost * (1 + 1e-9));
    }
  }

  // Raising c2 (c1 : c3 kept) never lowers the MRR of the selected point (a theorem for an exact argmin).
  void raisingC2NeverLowersMrr_data() {
    QTest::addColumn<double>("share1");  // c1 / (c1 + c3)
    QTest::newRow("c1 only") << 1.0;
    QTest::newRow("paper ratio") << 0.2 / 0.275;
    QTest::newRow("balanced") << 0.5;
    QTest::newRow("c3 only") << 0.0;
  }
  void raisingC2NeverLowersMrr() {
    QFETCH(double, share1);
    double previous = 0.0;
    for (int i = 0; i <= 50; ++i) {
      const double c2 = 0.02 * i, rest = 1.0 - c2;
      const ToolChoice q = test::rubioSession().rank({share1 * rest, c2, (1.0 - share1) * rest}).selected();
      QVERIFY2(q.q.mrr_m3_per_s >= previous * (1.0 - 1e-9), qPrintable(QString("c2 = %1").arg(c2)));
      previous = q.q.mrr_m3_per_s;
    }
    QVERIFY(previous > 0.0);
  }

  // Rule 5: q** from cached simulations (the best 12 by C and the search's); re-weighing runs no new one.
  void refinementIsCached() {
    ExpertSession session({test::rubioR1(), test::rubioR2()}, test::rubioExpertSettings());
    CostWeights w;
    const ExpertResult first = session.run(w, true);
    QVERIFY(first.refinement.has_value());
    QCOMPARE(first.refinement->seed_count, std::size_t(12));
    const std::size_t simulated = first.refinement->candidates.size();
    QCOMPARE(session.simulations().simulationsRun(), simulated);
    QCOMPARE(first.malfunction_iterations, 0);
    const ExpertPoint qss = first.refinement->chosen().q;
    qInfo("q** = (%.3f rpm, %.4f mm, %.4f mm), P = %.2f W", qss.speed_rev_per_s * 60, qss.depth_m * 1e3,
          qss.feed_per_tooth_m * 1e3, qss.power_w);
    QVERIFY(session.grid(kR1).isAdmissible(qss.speed_rev_per_s, qss.depth_m, qss.feed_per_tooth_m));
    for (const RefinementCandidate& c : first.refinement->candidates) QVERIFY(!c.metrics.chatter);
    for (double c1 : {0.1, 0.3, 0.5}) session.rank({c1, 0.9 - c1, 0.1});
    const ExpertResult again = session.run(w, true);
    QCOMPARE(session.simulations().simulationsRun(), simulated);
    QCOMPARE(again.refinement->chosen().q.depth_m, qss.depth_m);
    const ExpertResult plain = session.run(w, false);
    QVERIFY(!plain.refinement.has_value());
  }

  // Rule 6 forced to fire every time: stops at 200 iterations, weights on the simplex, c2 -> 0.99^200 c2.
  void malfunctionLoopStaysOnSimplex() {
    ExpertSettings s = test::rubioExpertSettings();
    s.refinement.malfunction_ratio = 0.0;  // A_chatter > 0 always holds
    s.refinement.simulated_points = 4;
    s.refinement.search.max_iterations = 0;  // the best 4 by C only: 200 Rule 6 rounds without a search each
    ExpertSession session({test::rubioR1(), test::rubioR2()}, s);
    const ExpertResult r = session.run(CostWeights{}, true);
    QCOMPARE(r.malfunction_iterations, 200);
    QVERIFY(r.malfunction_limit_reached);
    const auto& c = r.weights.c;
    QCOMPARE_LE(std::abs(c[0] + c[1] + c[2] - 1.0), 1e-12);
    for (double v : c) QVERIFY(v >= 0.0);
    QCOMPARE_LE(std::abs(c[0] - 0.2), 1e-12);
    QCOMPARE_LE(std::abs(c[1] - 0.725 * std::pow(0.99, 200)), 1e-12);
  }

  // Rule 6 on reported chatter, Rule 4 only: chatter heard at q* moves the weights by the Rule 6 step
  // until q* leaves the reported region; one step fewer leaves it inside (the loop stops at once).
  void reportedChatterMovesQStar() {
    ExpertSession session({test::rubioR1(), test::rubioR2()}, test::rubioExpertSettings());
    const CostWeights w;
    const ExpertPoint q0 = session.rank(w.c).selected().q;
    ChatterReport heard;
    heard.tool = kR1;
    heard.speed_rev_per_s = q0.speed_rev_per_s;
    heard.depth_m = q0.depth_m;
    heard.frequency_hz = 640.0;
    const ExpertResult r = session.run(w, false, {heard});
    const int n = r.malfunction_iterations;
    const ExpertPoint& q = r.chosenPoint();
    qInfo("reported at q* (%.0f rpm, %.4f mm): %d steps, q* -> (%.0f rpm, %.4f mm, %.3f mm), c = (%.4f, %.4f, %.4f)",
          q0.speed_rev_per_s * 60, q0.depth_m * 1e3, n, q.speed_rev_per_s * 60, q.depth_m * 1e3,
          q.feed_per_tooth_m * 1e3, r.weights.c[0], r.weights.c[1], r.weights.c[2]);
    QVERIFY(n > 0);
    QCOMPARE(r.reported_chatter_iterations, n);
    QVERIFY(!r.malfunction_limit_reached);
    QVERIFY(!chatterRegionOf(heard).contains(q.speed_rev_per_s, q.depth_m));
    QVERIFY(session.grid(r.chosenTool()).isAdmissible(q.speed_rev_per_s, q.depth_m, q.feed_per_tooth_m));
    // The Rule 6 step moves 1 % of c2 to c3 each time: c2 = 0.99^n c2(0), c1 unchanged.
    QCOMPARE_LE(std::abs(r.weights.c[1] - 0.725 * std::pow(0.99, n)), 1e-12);
    QCOMPARE_LE(std::abs(r.weights.c[2] - (0.075 + 0.725 * (1.0 - std::pow(0.99, n)))), 1e-12);
    QCOMPARE_LE(std::abs(r.weights.c[0] - 0.2), 1e-12);
    std::array<double, 3> before = w.c;
    for (int i = 0; i + 1 < n; ++i) before = malfunctionStep(before);
    const Ranking previous = session.rank(before);
    QCOMPARE(previous.selected().tool, kR1);
    QVERIFY(chatterRegionOf(heard).contains(previous.selected().q.speed_rev_per_s, previous.selected().q.depth_m));
  }

  // A report of the other tool, or clear of q*, does not fire Rule 6.
  void reportElsewhereDoesNotFire() {
    ExpertSession session({test::rubioR1(), test::rubioR2()}, test::rubioExpertSettings());
    const ExpertPoint q0 = session.rank(CostWeights{}.c).selected().q;
    ChatterReport other;
    other.tool = kR2;
    other.speed_rev_per_s = q0.speed_rev_per_s;
    other.depth_m = q0.depth_m;
    ChatterReport deeper;
    deeper.tool = kR1;
    deeper.speed_rev_per_s = q0.speed_rev_per_s;
    deeper.depth_m = 1.5 * q0.depth_m;
    const ExpertResult r = session.run(CostWeights{}, false, {other, deeper});
    QCOMPARE(r.malfunction_iterations, 0);
    QCOMPARE(r.chosenPoint().depth_m, q0.depth_m);
  }

  // At its bound the loop stops with the report that still holds the chosen point.
  void reportedChatterStopsAtBound() {
    ExpertSettings s = test::rubioExpertSettings();
    s.refinement.max_malfunction_iterations = 2;
    ExpertSession session({test::rubioR1(), test::rubioR2()}, s);
    const ExpertPoint q0 = session.rank(CostWeights{}.c).selected().q;
    ChatterReport heard;
    heard.tool = kR1;
    heard.speed_rev_per_s = q0.speed_rev_per_s;
    heard.depth_m = 1e-6;  // every depth at this speed chatters
    const ExpertResult r = session.run(CostWeights{}, false, {heard});
    QCOMPARE(r.malfunction_iterations, 2);
    QVERIFY(r.malfunction_limit_reached);
    QCOMPARE(r.unresolved_report, std::optional<std::size_t>(0));
    ChatterReport bad = heard;
    bad.tool = 5;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, session.run(CostWeights{}, false, {bad}));
  }

  // Module II per tool: R1's F_allow = 60 N (its unlimited q* peaks near 85 N) keeps R1's q* under
  // 60 N; R2 without a limit keeps its Q; a 1 mN limit on R1 leaves R2 alone in the ranking.
  void toolForceLimitsActPerTool() {
    const double inf = std::numeric_limits<double>::infinity();
    const std::array<double, 3> c{0.2, 0.725, 0.075};
    const ExpertSession limited({test::rubioR1(), test::rubioR2()}, test::rubioExpertSettings(), {60.0, inf});
    const std::vector<ToolChoice> free_best = test::rubioSession().bestPoints(kR1, c, 1);
    const ExpertPoint free_q = free_best.front().q;
    QCOMPARE_GE(
        evaluateCut(test::rubioR1(), {free_q.speed_rev_per_s, free_q.depth_m, free_q.feed_per_tooth_m}).peak_force_n,
        80.0);
    const ExpertPoint q = limited.bestPoints(kR1, c, 1).front().q;
    QCOMPARE_LE(evaluateCut(test::rubioR1(), {q.speed_rev_per_s, q.depth_m, q.feed_per_tooth_m}).peak_force_n,
                60.0 * (1 + 1e-9));
    QCOMPARE(limited.grid(kR1).settings().limits.max_tool_force_n, 60.0);
    // R2's Q is untouched (its q* may move: NF1..NF3 are taken over every tool's Q).
    QVERIFY(std::isinf(limited.grid(kR2).settings().limits.max_tool_force_n));
    QCOMPARE(limited.grid(kR2).pointCount(), test::rubioSession().grid(kR2).pointCount());
    QCOMPARE_LT(limited.grid(kR1).pointCount(), test::rubioSession().grid(kR1).pointCount());

    const ExpertSession r1_out({test::rubioR1(), test::rubioR2()}, test::rubioExpertSettings(), {1e-3, inf});
    QVERIFY(!r1_out.empty());
    const Ranking ranking = r1_out.rank(c);
    QCOMPARE(ranking.tools.size(), std::size_t(1));
    QCOMPARE(ranking.selected().tool, kR2);
    QCOMPARE(ranking.excluded, std::vector<std::size_t>{kR1});

    const ExpertSession none({test::rubioR1(), test::rubioR2()}, test::rubioExpertSettings(), {1e-3, 1e-3});
    QVERIFY(none.empty());
    QVERIFY2(QString::fromStdString(none.emptyReason()).contains("tool force limit F_allow (0.001 N"),
             none.emptyReason().c_str());
    QVERIFY_THROWS_EXCEPTION(InvalidInput,
                             ExpertSession({test::rubioR1(), test::rubioR2()}, test::rubioExpertSettings(), {60.0}));
  }

  void emptySpaceNamesConstraint() {
    ExpertSettings s = test::rubioExpertSettings();
    s.limits.spindle_power_w = 1e-3;
    const ExpertSession session({test::rubioR1(), test::rubioR2()}, s);
    QVERIFY(session.empty());
    QVERIFY(QString::fromStdString(session.emptyReason()).contains("spindle power limit (0.001 W)"));
    QVERIFY(session.rank({0.2, 0.725, 0.075}).tools.empty());
    QVERIFY_THROWS_EXCEPTION(InvalidInput, session.rank({0.5, 0.6, 0.0}));
  }
};

MX_REGISTER_TEST(TestExpertSession)
#include "test_expert_session.moc"
