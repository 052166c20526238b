// Rule 9 normalisations of the objective table (case study, 100 rpm grid): each variant's formula on
// Q's ranges, the non-dominated set that none of them changes (each is strictly monotone per
// objective), and the reason for the project default "log": under min-max the steep power laws give
// almost all of Q a tool-life score near 0.
#include <algorithm>
#include <cmath>
#include <vector>

#include "pareto/objective_table.h"
#include "pareto/pareto_front.h"
#include "pareto_fixtures.h"
#include "test_registry.h"

using namespace mx;

namespace {
const ObjectiveTable& tableWith(ParetoNormalisation n) {
  static const ObjectiveTable minmax(test::paretoCaseGrid(), ParetoModels{}, ParetoNormalisation::MinMax);
  static const ObjectiveTable max(test::paretoCaseGrid(), ParetoModels{}, ParetoNormalisation::Max);
  static const ObjectiveTable log(test::paretoCaseGrid(), ParetoModels{}, ParetoNormalisation::Log);
  return n == ParetoNormalisation::MinMax ? minmax : n == ParetoNormalisation::Max ? max : log;
}

double medianScore(const ObjectiveTable& t, Objective o) {
  std::vector<double> v;
  for (const ObjectiveVector& s : t.scores()) v.push_back(s[index(o)]);
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}
}  // namespace

class TestObjectiveTable : public QObject {
  Q_OBJECT
 private slots:
  void formulas_data() {
    QTest::addColumn<int>("normalisation");
    QTest::newRow("minmax") << int(ParetoNormalisation::MinMax);
    QTest::newRow("max") << int(ParetoNormalisation::Max);
    QTest::newRow("log") << int(ParetoNormalisation::Log);
  }
  void formulas() {
    QFETCH(int, normalisation);
    const auto kind = static_cast<ParetoNormalisation>(normalisation);
    const ObjectiveTable& t = tableWith(kind);
    QCOMPARE(t.normalisation(), kind);
    const ObjectiveRange& r = t.range();
    for (std::size_t i = 0; i < t.size(); i += 97) {
      const ObjectiveVector& x = t.points()[i].objectives;
      for (std::size_t k = 0; k < kObjectiveCount; ++k) {
        const double lo = r.min[k], hi = r.max[k];
        const bool power_law = k == index(Objective::ToolLife) || k == index(Objective::Roughness);
        double expected = (x[k] - lo) / (hi - lo);
        if (kind == ParetoNormalisation::Max) expected = x[k] / hi;
        if (kind == ParetoNormalisation::Log && power_law) expected = std::log(x[k] / lo) / std::log(hi / lo);
        if (isMinimised(k)) expected = kind == ParetoNormalisation::Max ? 1.0 - x[k] / hi : 1.0 - expected;
        QCOMPARE_LE(std::abs(t.scores()[i][k] - expected), 1e-12);
      }
    }
  }

  // Invariant: the non-dominated set is the same under every normalisation.
  void frontDoesNotDependOnTheNormalisation() {
    const auto front = nonDominated(tableWith(ParetoNormalisation::MinMax).scores());
    QVERIFY(front.size() > 10);
    QCOMPARE(nonDominated(tableWith(ParetoNormalisation::Max).scores()), front);
    QCOMPARE(nonDominated(tableWith(ParetoNormalisation::Log).scores()), front);
  }

  // TOL spans 4 decades over Q (0.50 to 4019 min): min-max leaves the median point a tool-life score
  // of 0.006 (and a smoothness score of 0.84), so the TOL weight acts only near the lower corner; log
  // puts both medians near the middle (0.44, 0.36).
  void logSpreadsThePowerLaws() {
    const ObjectiveTable& minmax = tableWith(ParetoNormalisation::MinMax);
    const ObjectiveTable& log = tableWith(ParetoNormalisation::Log);
    qInfo("TOL over Q: %.4g to %.4g min; SURF %.4g to %.4g um", minmax.range().min[0], minmax.range().max[0],
          minmax.range().min[2], minmax.range().max[2]);
    qInfo("median TOL score: minmax %.2e, log %.3f; median SURF score: minmax %.3f, log %.3f",
          medianScore(minmax, Objective::ToolLife), medianScore(log, Objective::ToolLife),
          medianScore(minmax, Objective::Roughness), medianScore(log, Objective::Roughness));
    QCOMPARE_LT(medianScore(minmax, Objective::ToolLife), 0.01);
    QCOMPARE_GT(medianScore(minmax, Objective::Roughness), 0.8);
    QCOMPARE_GT(medianScore(log, Objective::ToolLife), 0.2);
    QCOMPARE_LT(medianScore(log, Objective::ToolLife), 0.8);
    QCOMPARE_GT(medianScore(log, Objective::Roughness), 0.2);
    QCOMPARE_LT(medianScore(log, Objective::Roughness), 0.8);
  }
};

MX_REGISTER_TEST(TestObjectiveTable)
#include "test_objective_table.moc"
