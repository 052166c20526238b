// The Pareto choice summary: the objective and normalisation combo boxes emit their keys once per
// user choice and nothing from the setters, the economic objectives are disabled without
// pareto.economics, and the summary shows q, the cost and time per part, and one line per binding limit.
#include <QComboBox>
#include <QLabel>
#include <QSignalSpy>
#include <QStandardItemModel>

#include "pareto_choice_summary.h"
#include "test_registry.h"

using mx::widgets::ParetoChoiceSummary;
using mx::widgets::ParetoChoiceSummaryPanel;

class TestParetoChoiceSummary : public QObject {
  Q_OBJECT
 private slots:
  void choicesEmitKeys() {
    ParetoChoiceSummaryPanel panel;
    QSignalSpy objective(&panel, &ParetoChoiceSummaryPanel::objectiveChosen);
    QSignalSpy normalisation(&panel, &ParetoChoiceSummaryPanel::normalisationChosen);
    panel.setObjective("max_rate");
    panel.setNormalisation("minmax");
    QCOMPARE(objective.count(), 0);
    QCOMPARE(normalisation.count(), 0);
    QCOMPARE(panel.objectiveCombo()->currentData().toString(), QString("max_rate"));
    QCOMPARE(panel.normalisationCombo()->currentData().toString(), QString("minmax"));
    emit panel.objectiveCombo()->activated(1);
    emit panel.normalisationCombo()->activated(0);
    QCOMPARE(objective.count(), 1);
    QCOMPARE(objective.first().first().toString(), QString("min_cost"));
    QCOMPARE(normalisation.first().first().toString(), QString("log"));
  }

  void economicObjectivesNeedEconomics() {
    ParetoChoiceSummaryPanel panel;
    auto* model = qobject_cast<QStandardItemModel*>(panel.objectiveCombo()->model());
    panel.setEconomicsAvailable(false);
    QVERIFY(model->item(0)->isEnabled());
    QVERIFY(!model->item(1)->isEnabled() && !model->item(2)->isEnabled());
    panel.setEconomicsAvailable(true);
    QVERIFY(model->item(1)->isEnabled() && model->item(2)->isEnabled());
  }

  void summaryText() {
    ParetoChoiceSummaryPanel panel;
    QCOMPARE(panel.pointLabel()->text(), QString("\u2014"));
    ParetoChoiceSummary s;
    s.speed_rpm = 1220;
    s.depth_mm = 0.4328;
    s.feed_mm_per_tooth = 0.3;
    s.mrr_cm3_s = 0.2376;
    s.tol_min = 45.56;
    s.surf_um = 2.009;
    s.ros = 0.668;
    s.cost_per_part = 12.5;
    s.time_per_part_min = 10.75;
    s.binding = {"Rule 11 requirement: MRR >= 0.2375 cm\u00b3/s", "feed per tooth 0.31 mm would break the maximum"};
    panel.setSummary(s);
    const QString text = panel.pointLabel()->text();
    for (const char* part : {"1220 rpm", "depth 0.4328 mm", "0.3000 mm/tooth", "MRR 14.26 cm³/min", "ROS 0.668",
                             "Cost per part 12.50", "time per part 10.75 min"})
      QVERIFY2(text.contains(QString::fromUtf8(part)), qPrintable(text));
    QCOMPARE(panel.bindingLabel()->text().count(QChar(0x2022)), 2);
    s.binding.clear();
    s.cost_per_part.reset();
    panel.setSummary(s);
    QVERIFY(panel.bindingLabel()->text().startsWith("no limit"));
    QVERIFY(!panel.pointLabel()->text().contains("Cost"));
  }
};

MX_REGISTER_TEST(TestParetoChoiceSummary)
#include "test_pareto_choice_summary.moc"
