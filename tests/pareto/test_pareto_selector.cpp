// The objective table over Q of the case study (Rule 9 scores in [0, 1], SURF reversed), the coarse
// selection (Rule 10.1: the maximum J over Q, on the Pareto set), the fine search (Rule 10.2: never a
// worse J, admissible), and the non-dominated set of the grid (admissible, non-dominated).
#include "pareto/objective_table.h"
#include "pareto/pareto_front.h"
#include "pareto/pareto_selector.h"
#include "pareto_fixtures.h"
#include "test_registry.h"

using namespace mx;

class TestParetoSelector : public QObject {
  Q_OBJECT
 private slots:
  void scoresNormalised() {
    const ObjectiveTable& t = test::paretoCaseTable();
    QVERIFY(t.size() > 1000);
    for (std::size_t i = 0; i < t.size(); ++i)
      for (std::size_t k = 0; k < kObjectiveCount; ++k) {
        QVERIFY(t.scores()[i][k] >= -1e-12 && t.scores()[i][k] <= 1.0 + 1e-12);
      }
    // SURF reversed: the smoothest point scores 1.
    std::size_t smooth = 0;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t.points()[i].surf() < t.points()[smooth].surf()) smooth = i;
    QCOMPARE(t.scores()[smooth][index(Objective::Roughness)], 1.0);
  }

  void paretoSetAdmissibleAndNonDominated() {
    const ObjectiveTable& t = test::paretoCaseTable();
    const auto front = nonDominated(t.scores());
    QVERIFY(!front.empty());
    QCOMPARE(front, nonDominatedBruteForce(t.scores()));
    for (std::size_t i : front) {
      const ParetoPoint& p = t.points()[i];
      QVERIFY(t.grid().isAdmissible(p.speed_rev_per_s, p.depth_m, p.feed_per_tooth_m));
    }
  }

  void coarseAndFine_data() {
    QTest::addColumn<ParetoWeights>("w");
    QTest::newRow("tool, surface, stability") << ParetoWeights{0.4, 0.1, 0.3, 0.2};
    QTest::newRow("productivity") << ParetoWeights{0.05, 0.8, 0.05, 0.1};
    QTest::newRow("balanced") << ParetoWeights{0.25, 0.25, 0.25, 0.25};
    QTest::newRow("ros only") << ParetoWeights{0.0, 0.0, 0.0, 1.0};
    QTest::newRow("mrr and ros") << ParetoWeights{0.0, 0.6, 0.0, 0.4};
  }
  void coarseAndFine() {
    QFETCH(ParetoWeights, w);
    const ObjectiveTable& t = test::paretoCaseTable();
    const ParetoSelector sel(t);
    const ParetoSelection c = sel.coarse(w);
    for (const ObjectiveVector& s : t.scores()) QVERIFY(objectiveJ(w, s) <= c.j + 1e-12);
    // With all weights > 0, the maximiser of J is non-dominated.
    if (w[0] > 0 && w[1] > 0 && w[2] > 0 && w[3] > 0)
      for (const ObjectiveVector& s : t.scores()) QVERIFY(!dominates(s, c.scores));
    const ParetoSelection f = sel.fine(c, w, FineSearchSettings{4});
    QVERIFY2(f.j >= c.j, qPrintable(QString("fine %1 < coarse %2").arg(f.j).arg(c.j)));
    QVERIFY(t.grid().isAdmissible(f.point.speed_rev_per_s, f.point.depth_m, f.point.feed_per_tooth_m));
    QVERIFY(f.candidates > 1);
  }

  void filterRestrictsSelection() {
    const ParetoSelector sel(test::paretoCaseTable());
    const ObjectiveRequirement req{Objective::Mrr, 0.2e-6, 0.4e-6};
    const ParetoSelection s = sel.coarse({0.4, 0.1, 0.3, 0.2}, req);
    QVERIFY(s.filtered);
    QVERIFY(req.satisfiedBy(s.point));
    const ParetoSelection none = sel.coarse({0.4, 0.1, 0.3, 0.2}, ObjectiveRequirement{Objective::Mrr, 1.0, 2.0});
    QVERIFY(!none.filtered);
  }
};

MX_REGISTER_TEST(TestParetoSelector)
#include "test_pareto_selector.moc"
