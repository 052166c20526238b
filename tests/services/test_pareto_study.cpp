// ParetoStudy (the shared CLI/GUI Pareto pipeline): the front is the non-dominated set of the table
// and every point of it is admissible; supportingWeights() gives weights under which Rule 10.1 selects
// that very point; choose() keeps the weights on the simplex and honours the point rules.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <algorithm>
#include <cmath>

#include "document/project.h"
#include "model/cutting_force.h"
#include "pareto/economic_selection.h"
#include "pareto/pareto_front.h"
#include "services/pareto_study.h"
#include "test_registry.h"

using namespace mx;
using namespace mx::app;

namespace {
Project caseProject(const QStringList& rules = {}, const QJsonObject& pareto_extra = {}) {
  QFile in(MX_PROJECTS_DIR "/rubio-pareto-case.mxproj");
  in.open(QIODevice::ReadOnly);
  QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
  if (!rules.isEmpty()) root["operator_rules"] = QJsonArray::fromStringList(rules);
  QJsonObject pareto = root["pareto"].toObject();
  for (auto it = pareto_extra.begin(); it != pareto_extra.end(); ++it) {
    if (it.value().isNull())
      pareto.remove(it.key());
    else
      pareto[it.key()] = it.value();
  }
  root["pareto"] = pareto;
  return projectFromJson(root);
}

// The case study with R1's tools[0].max_force_N replaced (<= 0: removed), and a control breakage limit.
Project caseWithForceLimit(double max_force_n, double breakage_n = 0.0, double safety_factor = 1.0) {
  Project p = caseProject();
  p.tools[0].max_force_N = max_force_n > 0.0 ? std::optional<double>(max_force_n) : std::nullopt;
  if (breakage_n > 0.0) {
    p.control->breakage_force_N = breakage_n;
    p.control->safety_factor = safety_factor;
  }
  return p;
}

bool onFront(const ParetoStudy& study, const ParetoChoice& c) {
  const auto& f = study.front();
  return c.selection.table_index && std::find(f.begin(), f.end(), *c.selection.table_index) != f.end();
}

bool hasBinding(const ParetoChoice& c, const QString& key) {
  return std::any_of(c.binding.begin(), c.binding.end(), [&](const BindingLimit& b) { return b.key == key; });
}
}  // namespace

class TestParetoStudy : public QObject {
  Q_OBJECT
 private slots:
  void frontIsNonDominatedAndAdmissible() {
    const ParetoStudy study(caseProject());
    const auto& front = study.front();
    QVERIFY(front.size() > 10);
    QCOMPARE(front, nonDominatedBruteForce(study.table().scores()));
    for (std::size_t i : front) {
      const ParetoPoint& p = study.table().points()[i];
      QVERIFY(study.grid().isAdmissible(p.speed_rev_per_s, p.depth_m, p.feed_per_tooth_m));
    }
  }
  void supportingWeightsSelectTheirPoint_data() {
    QTest::addColumn<QString>("normalisation");
    QTest::newRow("log") << "log";
    QTest::newRow("minmax") << "minmax";
    QTest::newRow("max") << "max";
  }
  void supportingWeightsSelectTheirPoint() {
    QFETCH(QString, normalisation);
    const ParetoStudy study(caseProject({}, {{"normalisation", normalisation}}));
    const auto weights = study.supportingWeights(12);
    QCOMPARE(weights.size(), study.front().size());
    int supported = 0;
    for (std::size_t k = 0; k < weights.size(); ++k) {
      if (!weights[k]) continue;
      ++supported;
      QVERIFY(onSimplex(*weights[k], 1e-12));
      ParetoChoiceOptions o;
      o.weights = *weights[k];
      o.project_requirement = false;
      const ParetoChoice c = study.choose(o);
      // Ties in J allowed: the chosen point scores the same J as the supported one.
      const double jk = objectiveJ(*weights[k], study.table().scores()[study.front()[k]]);
      QCOMPARE_LE(std::abs(c.selection.j - jk), 1e-12);
    }
    qInfo("%d of %zu front points supported", supported, weights.size());
    QVERIFY(supported >= 4);
  }

  // With the project's minimum MRR, how many distinct points the weights of a 0.1 simplex lattice
  // select, per normalisation (docs/fidelity.md compares them).
  void weightsSteerTheChoice_data() { supportingWeightsSelectTheirPoint_data(); }
  void weightsSteerTheChoice() {
    QFETCH(QString, normalisation);
    const ParetoStudy study(caseProject({}, {{"normalisation", normalisation}}));
    std::vector<std::size_t> chosen;
    int rounds = 0;
    for (int a = 0; a <= 10; ++a)
      for (int b = 0; a + b <= 10; ++b)
        for (int c = 0; a + b + c <= 10; ++c) {
          ParetoChoiceOptions o;
          o.weights = ParetoWeights{a / 10.0, b / 10.0, c / 10.0, (10 - a - b - c) / 10.0};
          chosen.push_back(*study.choose(o).selection.table_index);
          ++rounds;
        }
    std::sort(chosen.begin(), chosen.end());
    const auto distinct = std::unique(chosen.begin(), chosen.end()) - chosen.begin();
    qInfo("%s: %td distinct points for %d weight vectors", qPrintable(normalisation), distinct, rounds);
    QVERIFY(distinct >= 3);
  }
  void chooseHonoursRules() {
    const ParetoStudy study(caseProject({"speed_rpm <= 2000", "weight.ros >= 0.5"}));
    ParetoChoiceOptions o;
    o.weights = ParetoWeights{0.4, 0.4, 0.1, 0.1};
    o.fine = true;
    const ParetoChoice c = study.choose(o);
    QVERIFY(revPerSToRpm(c.point().speed_rev_per_s) <= 2000.0 + 1e-9);
    QVERIFY(c.weights[3] >= 0.5 - 1e-12);
    QVERIFY(onSimplex(c.weights, 1e-12));
    QVERIFY(c.selection.j >= c.coarse_j - 1e-12);  // the fine search never loses
  }

  // The project's default weights (preserve the tool and the surface, 0.4 and 0.3) with the shop's
  // default minimum MRR (25 % of Q's largest): a point on the front, away from the grid's lower corner,
  // inside every limit, with the requirement named as binding. Without it, the lower corner.
  void defaultWeightsGiveARunnablePoint() {
    const ParetoStudy study(caseProject({}, {{"requirements", QJsonValue()}}));
    QVERIFY(study.request().minimum_mrr.is_default);
    const ParetoChoice c = study.choose({});
    QVERIFY2(c.requirement_text.contains("shop default"), qPrintable(c.requirement_text));
    const ParetoPoint& q = c.point();
    const AdmissibleGrid& g = study.grid();
    QVERIFY(onFront(study, c));
    QVERIFY(g.isAdmissible(q.speed_rev_per_s, q.depth_m, q.feed_per_tooth_m));
    QCOMPARE_GT(q.speed_rev_per_s, g.speeds().front());
    QCOMPARE_GE(q.depth_m, 3.0 * g.depthStep());
    QCOMPARE_GE(q.feed_per_tooth_m, 3.0 * g.feedStep());
    QVERIFY(c.requirement_satisfied && c.requirement_binding);
    QCOMPARE_GE(q.mrr(), kDefaultMinMrrFraction * study.table().range().max[index(Objective::Mrr)] * (1 - 1e-12));
    QVERIFY(hasBinding(c, "requirement"));
    QCOMPARE(c.weights, (ParetoWeights{0.4, 0.1, 0.3, 0.2}));  // a constraint, not a weight change
    QVERIFY(q.ros() > 0.3);

    ParetoChoiceOptions none;
    none.project_requirement = false;
    const ParetoChoice corner = study.choose(none);
    QCOMPARE(corner.point().depth_m, g.depthStep());
    QCOMPARE(corner.point().feed_per_tooth_m, g.feedStep());
    QVERIFY(!hasBinding(corner, "requirement"));
    QVERIFY(hasBinding(corner, "grid"));  // the lowest speed of the grid
  }

  // Module II in Q (Rules 3 and 7.1): F_allow = 30 N on R1. Every point of Q peaks at or under 30 N, and
  // the largest MRR (weights 0, 1, 0, 0) sits on the force limit: one more step of depth or of feed
  // breaks it (binding "tool_force" both ways). The control section's breakage limit 0.5 x 60 N gives
  // the same Q when the tool has no limit of its own.
  void toolForceLimitBoundsQ() {
    // The case project's own F_allow (600 N, its force reference) does not bind: Q's largest peak force
    // is far below it, and Q is the same without the limit.
    Project unlimited_project = caseProject();
    QCOMPARE(unlimited_project.tools[0].max_force_N, std::optional<double>(600.0));
    unlimited_project.tools[0].max_force_N.reset();
    const ParetoStudy free(unlimited_project);
    double largest = 0.0;
    for (const ParetoPoint& p : free.table().points())
      largest = std::max(
          largest, evaluateCut(free.grid().setup(), {p.speed_rev_per_s, p.depth_m, p.feed_per_tooth_m}).peak_force_n);
    qInfo("largest peak force over Q: %.2f N", largest);
    QCOMPARE_LT(largest, 200.0);
    QCOMPARE(ParetoStudy(caseProject()).table().size(), free.table().size());
    const ParetoStudy study(caseWithForceLimit(30.0));
    QCOMPARE_LT(study.table().size(), free.table().size());
    for (const ParetoPoint& p : study.table().points())
      QVERIFY(evaluateCut(study.grid().setup(), {p.speed_rev_per_s, p.depth_m, p.feed_per_tooth_m}).peak_force_n <=
              30.0 * (1 + 1e-9));
    ParetoChoiceOptions mrr;
    mrr.weights = ParetoWeights{0.0, 1.0, 0.0, 0.0};
    mrr.project_requirement = false;
    const ParetoChoice c = study.choose(mrr);
    const ParetoPoint& q = c.point();
    const double force =
        evaluateCut(study.grid().setup(), {q.speed_rev_per_s, q.depth_m, q.feed_per_tooth_m}).peak_force_n;
    QCOMPARE_LE(force, 30.0);
    int force_bound = 0;
    for (const BindingLimit& b : c.binding) {
      if (b.key != "tool_force") continue;
      ++force_bound;
      QVERIFY2(b.text.contains("tool force limit F_allow (30 N"), qPrintable(b.text));
    }
    QCOMPARE(force_bound, 2);  // depth and feed
    const ParetoStudy breakage(caseWithForceLimit(0.0, 60.0, 0.5));
    QCOMPARE(breakage.table().size(), study.table().size());
  }

  void requirementBases_data() {
    QTest::addColumn<QJsonObject>("requirements");
    QTest::addColumn<double>("expected_lo_cm3_s");  // < 0: the fraction times Q's largest MRR
    QTest::newRow("absolute") << QJsonObject{{"min_mrr_cm3_s", 0.1}} << 0.1;
    QTest::newRow("time for a volume") << QJsonObject{{"max_time_min", 10.0}, {"removal_volume_cm3", 90.0}} << 0.15;
    QTest::newRow("fraction") << QJsonObject{{"min_mrr_fraction", 0.5}} << -0.5;
  }
  void requirementBases() {
    QFETCH(QJsonObject, requirements);
    QFETCH(double, expected_lo_cm3_s);
    const ParetoStudy study(caseProject({}, {{"requirements", requirements}}));
    const double max_mrr = study.table().range().max[index(Objective::Mrr)];
    const double lo = expected_lo_cm3_s < 0.0 ? -expected_lo_cm3_s * max_mrr : expected_lo_cm3_s * 1e-6;
    QCOMPARE_LE(std::abs(study.projectRequirement().lo - lo), 1e-12 * lo);
    const ParetoChoice c = study.choose({});
    QVERIFY(c.requirement_satisfied);
    QCOMPARE_GE(c.point().mrr(), lo * (1 - 1e-12));
  }

  // min_cost and max_rate: the cheapest / fastest point meeting the requirement (brute force), with
  // the cost of the cheapest never above the weighted choice's.
  void economicObjectives() {
    const QJsonObject economics{
        {"machine_rate_per_h", 60.0}, {"tool_cost", 45.0}, {"tool_change_min", 2.0}, {"removal_volume_cm3", 150.0}};
    const ParetoStudy study(caseProject({}, {{"economics", economics}}));
    const ParetoChoice weighted = study.choose({});
    QVERIFY(weighted.economics.has_value());
    ParetoChoiceOptions o;
    o.objective = ParetoObjectiveKind::MinCost;
    const ParetoChoice cheap = study.choose(o);
    o.objective = ParetoObjectiveKind::MaxRate;
    const ParetoChoice fast = study.choose(o);
    const MachiningEconomics e = *study.request().economics;
    const ObjectiveRequirement r = study.projectRequirement();
    double best_cost = 1e300;
    for (const ParetoPoint& p : study.table().points())
      if (r.satisfiedBy(p)) best_cost = std::min(best_cost, pointEconomics(e, p).cost_per_part);
    QCOMPARE(cheap.economics->cost_per_part, best_cost);
    QVERIFY(cheap.economics->cost_per_part <= weighted.economics->cost_per_part);
    QVERIFY(fast.economics->time_per_part_s <= cheap.economics->time_per_part_s);
    QVERIFY(cheap.economics->cost_per_part <= fast.economics->cost_per_part);
    QVERIFY(onFront(study, cheap) || cheap.point().mrr() > 0.0);
  }

  void economicObjectiveNeedsEconomics() {
    QVERIFY_THROWS_EXCEPTION(ProjectError,
                             ParetoStudy(caseProject({}, {{"objective", "min_cost"}, {"economics", QJsonValue()}})));
  }
};

MX_REGISTER_TEST(TestParetoStudy)
#include "test_pareto_study.moc"
