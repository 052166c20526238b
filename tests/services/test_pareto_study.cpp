// ParetoStudy (the shared CLI/GUI Pareto pipeline): the front is the non-dominated set of the table
// and every point of it is admissible; supportingWeights() gives weights under which Rule 10.1 selects
// that very point; choose() keeps the weights on the simplex and honours the point rules.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <cmath>

#include "document/project.h"
#include "pareto/pareto_front.h"
#include "services/pareto_study.h"
#include "test_registry.h"

using namespace mx;
using namespace mx::app;

namespace {
Project caseProject(const QStringList& rules = {}) {
  QFile in(MX_PROJECTS_DIR "/rubio-pareto-case.mxproj");
  in.open(QIODevice::ReadOnly);
  QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
  if (!rules.isEmpty()) root["operator_rules"] = QJsonArray::fromStringList(rules);
  return projectFromJson(root);
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
  void supportingWeightsSelectTheirPoint() {
    const ParetoStudy study(caseProject());
    const auto weights = study.supportingWeights(12);
    QCOMPARE(weights.size(), study.front().size());
    int supported = 0;
    for (std::size_t k = 0; k < weights.size(); ++k) {
      if (!weights[k]) continue;
      ++supported;
      QVERIFY(onSimplex(*weights[k], 1e-12));
      const ParetoChoice c = study.choose({*weights[k], {}, false, false});
      // Ties in J allowed: the chosen point scores the same J as the supported one.
      const double jk = objectiveJ(*weights[k], study.table().scores()[study.front()[k]]);
      QCOMPARE_LE(std::abs(c.selection.j - jk), 1e-12);
    }
    QVERIFY(supported >= 5);
  }
  void chooseHonoursRules() {
    const ParetoStudy study(caseProject({"speed_rpm <= 2000", "weight.ros >= 0.5"}));
    const ParetoChoice c = study.choose({ParetoWeights{0.4, 0.4, 0.1, 0.1}, {}, true, false});
    QVERIFY(revPerSToRpm(c.point().speed_rev_per_s) <= 2000.0 + 1e-9);
    QVERIFY(c.weights[3] >= 0.5 - 1e-12);
    QVERIFY(onSimplex(c.weights, 1e-12));
    QVERIFY(c.selection.j >= c.coarse_j - 1e-12);  // the fine search never loses
  }
};

MX_REGISTER_TEST(TestParetoStudy)
#include "test_pareto_study.moc"
