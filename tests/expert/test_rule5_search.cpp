// The Rule 5 pattern search (2006, eq. 18-20): the search mechanics on synthetic responses over R1's
// admissible space (moves, halving, termination, admissibility), and q** of the 2006 example from
// time-domain simulations with its invariants.
#include <cmath>

#include "core/invalid_input.h"
#include "expert/expert_session.h"
#include "expert/rule5_search.h"
#include "expert_fixtures.h"
#include "test_registry.h"

using namespace mx;

namespace {
using test::kR1;

// A response whose overshoot grows with the scaled distance to `target`; the other figures constant.
// With c_r = (0, 1, 0), c_t = (0, 1) the search then minimises the distance to the target.
Rule5Problem distanceProblem(const ExpertPoint& target) {
  Rule5Problem p;
  p.grid = &test::rubioSession().grid(kR1);
  p.speed_from_rev_per_s = test::rubioExpertSettings().grid.speed_from_rev_per_s;
  p.speed_to_rev_per_s = test::rubioExpertSettings().grid.speed_to_rev_per_s;
  p.nf = test::rubioSession().normalisation();
  p.weights.cr = {0.0, 1.0, 0.0};
  p.weights.ct = {0.0, 1.0};
  p.simulate = [target](const std::vector<ExpertPoint>& points) {
    std::vector<ResponseMetrics> out;
    for (const ExpertPoint& q : points) {
      ResponseMetrics m;
      const double dn = (q.speed_rev_per_s - target.speed_rev_per_s) / (100.0 / 60.0);
      const double db = (q.depth_m - target.depth_m) / 0.01e-3;
      const double ds = (q.feed_per_tooth_m - target.feed_per_tooth_m) / 0.01e-3;
      m.overshoot = 1.0 + dn * dn + db * db + ds * ds;
      m.settling_time_s = 0.01;
      out.push_back(m);
    }
    return out;
  };
  return p;
}

ExpertPoint qStar() {
  return test::rubioSession().rank({0.2, 0.725, 0.075}).selected().q;
}

std::vector<ExpertPoint> bestByCost(std::size_t k) {
  std::vector<ExpertPoint> out;
  for (const ToolChoice& t : test::rubioSession().bestPoints(kR1, {0.2, 0.725, 0.075}, k)) out.push_back(t.q);
  return out;
}

Rule5Steps defaultSteps(const Rule5SearchSettings& s) {
  return rule5StartSteps(test::rubioSession().grid(kR1), test::rubioExpertSettings().grid, s);
}

double rpm(const ExpertPoint& q) {
  return q.speed_rev_per_s * 60.0;
}
}  // namespace

class TestRule5Search : public QObject {
  Q_OBJECT
 private slots:
  // At a grid point the arbitrary-point evaluation reproduces the grid's power, MRR and Delta N_s.
  void pointAtMatchesGrid() {
    const AdmissibleGrid& g = test::rubioSession().grid(kR1);
    for (std::size_t cell : {std::size_t(0), g.cells().size() / 2, g.cells().size() - 1}) {
      const ExpertPoint a = g.point(cell, 1);
      const ExpertPoint b = expertPointAt(g, a.speed_rev_per_s, a.depth_m, a.feed_per_tooth_m);
      QCOMPARE_LE(std::abs(b.power_w / a.power_w - 1.0), 1e-12);
      QCOMPARE_LE(std::abs(b.mrr_m3_per_s / a.mrr_m3_per_s - 1.0), 1e-12);
      QCOMPARE_LE(std::abs(b.speed_security / a.speed_security - 1.0), 1e-12);
    }
  }

  // Defaults from the 2006 grid: 1000 rpm / 4, b_min / 10 / 2, 0.01 mm / 2.
  void startStepsFromGrid() {
    const Rule5Steps s = defaultSteps({});
    QCOMPARE_LE(std::abs(s.speed_rev_per_s * 60.0 - 250.0), 1e-9);
    QCOMPARE_LE(std::abs(s.depth_m - test::rubioSession().grid(kR1).depthStep() / 2.0), 1e-15);
    QCOMPARE_LE(std::abs(s.feed_per_tooth_m - 0.005e-3), 1e-15);
    Rule5SearchSettings set;
    set.speed_step_rev_per_s = 2.0;
    QCOMPARE(defaultSteps(set).speed_rev_per_s, 2.0);
  }

  // The optimum at q*: the centre never moves, so every iteration halves the steps. Speed needs
  // 250 -> 7.8 rpm (5 halvings), depth 36 -> 0.56 um (6; R1's depth step is 72 um), feed 5 -> 0.63 um (3):
  // 6 iterations.
  void stepsHalveUntilTheResolutions() {
    const ExpertPoint q = qStar();
    const Rule5SearchSettings set;
    const Rule5Steps start = defaultSteps(set);
    const Rule5Result r = searchRule5(distanceProblem(q), q, {q}, start, set);
    QCOMPARE(r.iterations, 6);
    QVERIFY(r.converged);
    QCOMPARE_LE(std::abs(r.final_steps.speed_rev_per_s - start.speed_rev_per_s / 64.0), 1e-12);
    QCOMPARE_LE(std::abs(r.final_steps.feed_per_tooth_m - start.feed_per_tooth_m / 64.0), 1e-18);
    QVERIFY(r.final_steps.depth_m < 1e-6 && r.final_steps.depth_m * 2.0 >= 1e-6);
    QCOMPARE(rpm(r.candidates[r.best].q), rpm(q));
  }

  // The search walks to an optimum well inside Q, more than ten start steps away in depth and feed,
  // and finds it to the resolutions (10 rpm, 1 um, 1 um/tooth).
  void walksToAnInteriorOptimum() {
    const ExpertPoint target = expertPointAt(test::rubioSession().grid(kR1), 5680.0 / 60.0, 0.40e-3, 0.22e-3);
    QVERIFY(
        test::rubioSession().grid(kR1).isAdmissible(target.speed_rev_per_s, target.depth_m, target.feed_per_tooth_m));
    Rule5SearchSettings set;
    set.max_iterations = 80;
    const ExpertPoint q = qStar();
    const Rule5Result r = searchRule5(distanceProblem(target), q, {q}, defaultSteps(set), set);
    const ExpertPoint found = r.candidates[r.best].q;
    qInfo("found (%.2f rpm, %.5f mm, %.5f mm) in %d iterations, %zu points", rpm(found), found.depth_m * 1e3,
          found.feed_per_tooth_m * 1e3, r.iterations, r.candidates.size());
    QVERIFY(r.converged);
    QCOMPARE_LE(std::abs(rpm(found) - 5680.0), 10.0);
    QCOMPARE_LE(std::abs(found.depth_m - target.depth_m), 1e-6);
    QCOMPARE_LE(std::abs(found.feed_per_tooth_m - target.feed_per_tooth_m), 1e-6);
  }

  // Every scored point is admissible and inside the grid's speed range, even with the optimum outside Q.
  void scoresAdmissiblePointsOnly() {
    const AdmissibleGrid& g = test::rubioSession().grid(kR1);
    const ExpertPoint beyond = expertPointAt(g, 6500.0 / 60.0, 0.8e-3, 0.5e-3);  // over the power limit
    QVERIFY(!g.isAdmissible(beyond.speed_rev_per_s, beyond.depth_m, beyond.feed_per_tooth_m));
    Rule5SearchSettings set;
    const ExpertPoint q = qStar();
    const Rule5Problem p = distanceProblem(beyond);
    const Rule5Result r = searchRule5(p, q, {q}, defaultSteps(set), set);
    QVERIFY(r.candidates.size() > 1);
    for (const RefinementCandidate& c : r.candidates) {
      QVERIFY(g.isAdmissible(c.q.speed_rev_per_s, c.q.depth_m, c.q.feed_per_tooth_m));
      QVERIFY(rpm(c.q) <= 6000.0 + 1e-6);
    }
  }

  // The iteration limit ends the search (not converged); max_iterations = 0 scores the seeds only.
  void iterationLimit() {
    const ExpertPoint q = qStar();
    const ExpertPoint target = expertPointAt(test::rubioSession().grid(kR1), 5680.0 / 60.0, 0.40e-3, 0.22e-3);
    Rule5SearchSettings set;
    set.max_iterations = 3;
    const Rule5Result r = searchRule5(distanceProblem(target), q, {q}, defaultSteps(set), set);
    QCOMPARE(r.iterations, 3);
    QVERIFY(!r.converged);
    set.max_iterations = 0;
    const std::vector<ExpertPoint> seeds = bestByCost(12);
    const Rule5Result none = searchRule5(distanceProblem(target), q, seeds, defaultSteps(set), set);
    QCOMPARE(none.iterations, 0);
    QCOMPARE(none.candidates.size(), seeds.size());
  }

  // q** of the 2006 example from simulations, c_r = (0.8, 0.1, 0.1), c_t = c_f = (0.5, 0.5).
  // Ours: (5800 rpm, 0.2885 mm, 0.4725 mm/tooth), on the power limit; the paper: q** = (5680 rpm,
  // 0.457 mm, 0.265 mm/tooth) (docs/fidelity.md: t_s = 0 and R1ch is round-off at every point, so C_t
  // is M_p alone, which falls with the depth, and C keeps q** on the power limit).
  void paperExampleQStarStar() {
    ExpertSession session({test::rubioR1(), test::rubioR2()}, test::rubioExpertSettings());
    const CostWeights w;
    const Refinement r = session.refine(kR1, w);
    const RefinementCandidate& qss = r.chosen();
    qInfo(
        "q** = (%.3f rpm, %.5f mm, %.5f mm), C = %.5f, C_t = %.4f, C_f = %.4f, C_res = %.5f; %zu points, "
        "%d iterations, %zu simulations",
        rpm(qss.q), qss.q.depth_m * 1e3, qss.q.feed_per_tooth_m * 1e3, qss.cost, qss.time_cost, qss.frequency_cost,
        qss.resultant, r.candidates.size(), r.search_iterations, r.simulations_run);
    QCOMPARE_LE(std::abs(rpm(qss.q) - 5800.0), 1e-6);
    QCOMPARE_LE(std::abs(qss.q.depth_m * 1e3 - 0.28846), 1e-5);
    QCOMPARE_LE(std::abs(qss.q.feed_per_tooth_m * 1e3 - 0.4725), 1e-6);
    QCOMPARE_LE(std::abs(qss.resultant - 0.85333), 1e-4);
    QVERIFY(r.search_converged);
    QCOMPARE(r.seed_count, std::size_t(12));
    QCOMPARE(r.simulations_run, r.candidates.size());
    QVERIFY(session.grid(kR1).isAdmissible(qss.q.speed_rev_per_s, qss.q.depth_m, qss.q.feed_per_tooth_m));
    for (const RefinementCandidate& c : r.candidates) QVERIFY(qss.resultant <= c.resultant);

    // Never worse than choosing among the best K by C alone, both judged on the full set's normalisation.
    std::vector<RefinementCandidate> seeds(r.candidates.begin(), r.candidates.begin() + 12);
    const std::size_t seeds_only = selectByResultantCost(seeds, w);
    QVERIFY(qss.resultant <= r.candidates[seeds_only].resultant);
    QVERIFY(qss.resultant < r.candidates[seeds_only].resultant);  // strictly better on this example

    // A second refine re-uses every simulation.
    const Refinement again = session.refine(kR1, w);
    QCOMPARE(again.simulations_run, std::size_t(0));
    QCOMPARE(again.chosen().q.feed_per_tooth_m, qss.q.feed_per_tooth_m);

    // c_r = (1, 0, 0): C_resultant = C. The searched set contains q* (candidates[0]), so C(q**) <= C(q*);
    // finer points on the power limit and nearer 6000 rpm (larger Delta N_s) may beat the grid's q*.
    CostWeights c_only;
    c_only.cr = {1.0, 0.0, 0.0};
    const Refinement by_cost = session.refine(kR1, c_only);
    const RefinementCandidate& q_star = by_cost.candidates.front();
    QCOMPARE(rpm(q_star.q), rpm(qStar()));
    qInfo("c_r = (1, 0, 0): q** = (%.3f rpm, %.5f mm, %.5f mm), C = %.6f vs C(q*) = %.6f", rpm(by_cost.chosen().q),
          by_cost.chosen().q.depth_m * 1e3, by_cost.chosen().q.feed_per_tooth_m * 1e3, by_cost.chosen().cost,
          q_star.cost);
    QVERIFY(by_cost.chosen().cost <= q_star.cost);
    for (const RefinementCandidate& c : by_cost.candidates) QVERIFY(by_cost.chosen().cost <= c.cost * (1.0 + 1e-9));
  }
};

MX_REGISTER_TEST(TestRule5Search)
#include "test_rule5_search.moc"
