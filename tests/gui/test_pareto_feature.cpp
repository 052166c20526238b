// The Pareto expert system in the main window: the front view shows the study's
// non-dominated set and a click moves the operating point and the weights to the clicked point in one
// undoable step; Rule 11 requirements and Rule 12 automatic weights commit weights that keep the
// simplex; the operator-rules editor edits the project, restricts the choice and shows fired rules and
// violations; the history view lists what "Record point" stored; the monitoring dock shows the
// simulation's signals and identified frequencies (Rule 17). A study that ends just after an edit is
// dropped, not shown.
#include <QApplication>
#include <QJsonArray>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <cmath>

#include "document/project.h"
#include "history_view.h"
#include "main_window.h"
#include "monitoring_panel.h"
#include "notice_stack.h"
#include "operator_rules_editor.h"
#include "pareto_front_view.h"
#include "pareto_runner.h"
#include "pareto_weights_panel.h"
#include "requirements_panel.h"
#include "support/engine_hold.h"
#include "support/pareto_window.h"
#include "support/project_files.h"
#include "support/window_features.h"
#include "test_registry.h"

using namespace mx;

namespace {

// The learning thread has answered every record and history query (and the view shows the answer).

widgets::ParetoWeightsPanel* weightsPanelOf(const gui::MainWindow& w) {
  return test::windowPart<widgets::ParetoWeightsPanel>(w);
}

double weightAt(const gui::MainWindow& w, int i) {
  return app::projectToJson(*w.project()).value("pareto").toObject().value("weights").toArray().at(i).toDouble();
}
}  // namespace

class TestParetoFeature : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-test");
  }

  // Without a "pareto" section the front dock says so instead of an empty 0-1 plot; its button adds
  // a section with Rubio et al.'s laws (one undo step) and the front follows.
  void frontWithoutAStudySaysWhyAndAddsOne() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    window.resize(1600, 950);
    window.show();
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    auto* notice = test::windowPart<widgets::NoticeStack>(window, "paretoFrontNotice");
    QTRY_VERIFY(notice->noticeShown());
    QVERIFY2(notice->noticeText().contains("no Pareto study"), qPrintable(notice->noticeText()));
    QVERIFY(!window.project()->pareto);
    QSignalSpy shown(test::paretoOf(window), &gui::ParetoFeature::paretoShown);
    QTest::mouseClick(notice->actionButton(), Qt::LeftButton);
    QVERIFY(window.project()->pareto && window.project()->pareto->taylor);
    QCOMPARE(window.project()->pareto->taylor->speed_exponent, -3.02);
    QTRY_VERIFY(!notice->noticeShown());
    QTRY_VERIFY_WITH_TIMEOUT(test::paretoOf(window)->runner()->study() != nullptr, 120000);
    QCOMPARE_GT(test::paretoOf(window)->runner()->study()->front().size(), std::size_t{1});
    window.document()->undoStack()->undo();
    QVERIFY(!window.project()->pareto);
    QTRY_VERIFY(notice->noticeShown());  // the study is rebuilt once the edits pause
  }

  // A study that ends just after an edit is of the project before it: dropped, so that the first front
  // shown after the edit is its own (here a 5-tooth cutter after a 4-tooth one).
  void aStudyOfTheProjectBeforeAnEditIsDropped() {
    gui::MainWindow window;
    QVERIFY(test::openParetoCase(window));
    const QString tool = test::paretoOf(window)->runner()->study()->request().tool;
    app::Project edited = *window.project();
    app::ToolSpec* spec = nullptr;
    for (app::ToolSpec& t : edited.tools)
      if (t.id == tool) spec = &t;
    QVERIFY(spec);
    spec->teeth = 4;  // a 4-tooth study
    QCOMPARE(test::applyEditAndHoldItsResults(window, edited, [&] { return test::paretoOf(window)->runner()->busy(); }),
             QString());
    spec->teeth = 5;
    QSignalSpy shown(test::paretoOf(window), &gui::ParetoFeature::paretoShown);
    QCOMPARE(window.document()->applyEdit(edited, "teeth"), QString());
    QVERIFY(shown.wait(120000));
    QCOMPARE(test::paretoOf(window)->runner()->study()->tool().teeth, 5);
  }

  // The chart marks the choice of the study's tool once; a live weight move redraws that one marker.
  void choiceIsMarkedOnTheChartOfItsTool() {
    gui::MainWindow window;
    QVERIFY(test::openParetoCase(window));
    const QString tool = test::paretoOf(window)->runner()->study()->request().tool;
    test::contextOf(window)->setActiveTool(tool);
    const QString marker = QString("Pareto q (%1)").arg(tool);
    widgets::LobeChartView* chart = test::lobesOf(window)->chart();
    QCOMPARE(chart->markerNames().count(marker), 1);
    emit weightsPanelOf(window)->weightsChanged({0.1, 0.7, 0.1, 0.1});  // a live move redraws, once
    QCOMPARE(chart->markerNames().count(marker), 1);
  }

  void frontClickMovesPointAndWeights() {
    gui::MainWindow window;
    QVERIFY(test::openParetoCase(window));
    const auto& study = *test::paretoOf(window)->runner()->study();
    widgets::ParetoFrontView* view = test::windowPart<widgets::ParetoFrontView>(window);
    QCOMPARE(static_cast<std::size_t>(view->points().size()), study.front().size());
    // The selection of the project's weights is marked in the view.
    QVERIFY(view->selectedIndex() >= 0);
    // A supported point other than the current choice, far from it on the plot.
    int target = -1;
    for (int i = 0; i < view->points().size(); ++i)
      if (view->points()[i].weights && i != view->selectedIndex() &&
          (target < 0 ||
           std::abs(view->points()[i].mrr_cm3_s - view->points()[view->selectedIndex()].mrr_cm3_s) >
               std::abs(view->points()[target].mrr_cm3_s - view->points()[view->selectedIndex()].mrr_cm3_s)))
        target = i;
    QVERIFY(target >= 0);
    const auto before = window.document()->point();
    const double w0 = weightAt(window, 0);
    const widgets::ParetoPointView p = view->points()[target];
    emit view->pointActivated(p);  // what a click on it emits
    QCOMPARE_LE(std::abs(window.document()->point().speed_rpm - p.speed_rpm), 1e-6);
    QCOMPARE_LE(std::abs(window.document()->point().depth_mm - p.depth_mm), 1e-9);
    QCOMPARE_LE(std::abs(window.document()->point().feed_mm_per_tooth - p.feed_mm_per_tooth), 1e-9);
    for (int i = 0; i < 4; ++i) {
      QCOMPARE_LE(std::abs(weightAt(window, i) - (*p.weights)[static_cast<std::size_t>(i)]), 1e-12);
      QCOMPARE_LE(std::abs(weightsPanelOf(window)->weights()[static_cast<std::size_t>(i)] -
                           (*p.weights)[static_cast<std::size_t>(i)]),
                  1e-12);
    }
    // The weights select a point with the clicked point's J (Rule 10.1 on the front).
    const auto& choice = *test::paretoOf(window)->choice();
    double j = 0.0;
    const ObjectiveVector s = study.table().normalise(
        study.table().evaluate(rpmToRevPerS(p.speed_rpm), p.depth_mm * 1e-3, p.feed_mm_per_tooth * 1e-3).objectives);
    for (std::size_t i = 0; i < 4; ++i) j += (*p.weights)[i] * s[i];
    QCOMPARE_LE(std::abs(choice.selection.j - j), 1e-9);
    QCOMPARE(view->selectedIndex(), target);
    // One undo restores weights and point together.
    window.document()->undoStack()->undo();
    QCOMPARE(window.document()->point(), before);
    QCOMPARE_LE(std::abs(weightAt(window, 0) - w0), 1e-15);
  }

  void requirementAndAutoWeights() {
    gui::MainWindow window;
    QVERIFY(test::openParetoCase(window));
    const double mrr = test::paretoOf(window)->choice()->point().mrr() * 1e6;
    // Require at least twice the current MRR (Rule 11): the weights move and the choice meets it.
    widgets::RequirementsPanel* panel = test::windowPart<widgets::RequirementsPanel>(window);
    panel->setRequirement(widgets::RequirementView{1, 2.0 * mrr, 1e3});
    emit panel->requirementChanged();
    const auto& c = *test::paretoOf(window)->choice();
    QVERIFY(c.requirement_satisfied);
    QVERIFY(c.point().mrr() * 1e6 >= 2.0 * mrr);
    QVERIFY(onSimplex(weightsPanelOf(window)->weights(), 1e-9));
    QVERIFY(weightsPanelOf(window)->weights()[1] > 0.1);  // the MRR weight rose from 0.1
    QCOMPARE_LE(std::abs(weightAt(window, 1) - weightsPanelOf(window)->weights()[1]), 1e-12);
    // Rule 12 keeps the weights on the simplex and the requirement.
    emit panel->autoWeightsRequested();
    QVERIFY(onSimplex(weightsPanelOf(window)->weights(), 1e-9));
    QVERIFY(test::paretoOf(window)->choice()->requirement_satisfied);
  }

  void operatorRulesRestrictAndFire() {
    gui::MainWindow window;
    QVERIFY(test::openParetoCase(window));
    QSignalSpy shown(test::paretoOf(window), &gui::ParetoFeature::paretoShown);
    widgets::OperatorRulesEditor* editor = test::windowPart<widgets::OperatorRulesEditor>(window);
    editor->textEdit()->setPlainText("speed_rpm <= 1500\nif tool.teeth >= 2 then advise depth_mm <= 0.01");
    QVERIFY(editor->check());
    QCOMPARE(app::projectToJson(*window.project()).value("operator_rules").toArray().size(), 2);
    for (int i = 0;
         i < 60 && !(test::paretoOf(window)->choice() &&
                     revPerSToRpm(test::paretoOf(window)->choice()->point().speed_rev_per_s) <= 1500.0 + 1e-9);
         ++i)
      shown.wait(1000);
    QVERIFY(revPerSToRpm(test::paretoOf(window)->choice()->point().speed_rev_per_s) <= 1500.0 + 1e-9);
    test::contextOf(window)->setActiveTool(test::paretoOf(window)->runner()->study()->request().tool);
    QCOMPARE(editor->firedRules(), (QList<int>{1, 2}));
    // A point above 1500 rpm breaks line 1: the editor says so.
    auto pt = window.document()->point();
    pt.speed_rpm = 2500.0;
    window.document()->setPoint(pt);
    QVERIFY(editor->notes().join('\n').contains("Line 1 violated"));
    // A syntax error changes nothing in the project.
    editor->textEdit()->setPlainText("speed_rpm <=");
    QVERIFY(!editor->check());
    QCOMPARE(app::projectToJson(*window.project()).value("operator_rules").toArray().size(), 2);
  }

  void historyRecordsAndAppliesWeights() {
    QTemporaryDir dir;
    gui::MainWindow window;
    QVERIFY(test::openParetoCase(window));
    test::paretoOf(window)->setLearningDatabasePath(dir.filePath("learning.sqlite"));
    QVERIFY(test::waitForLearning(window));
    QCOMPARE(test::windowPart<widgets::HistoryView>(window)->rows().size(), 0);
    // Move to the Pareto choice (commit the current weights), record it: source automatic.
    const ParetoWeights w = weightsPanelOf(window)->weights();
    weightsPanelOf(window)->setWeights(w);
    emit weightsPanelOf(window)->weightsCommitted(w);
    test::paretoOf(window)->recordOperatingPoint();
    QVERIFY(test::waitForLearning(window));
    QCOMPARE(test::windowPart<widgets::HistoryView>(window)->rows().size(), 1);
    const widgets::HistoryRow row = test::windowPart<widgets::HistoryView>(window)->rows().front();
    QCOMPARE(row.source, QString("automatic"));
    QCOMPARE(row.tool, test::paretoOf(window)->runner()->study()->request().tool);
    QCOMPARE_LE(std::abs(row.speed_rpm - window.document()->point().speed_rpm), 1e-6);
    // Change the weights, then "apply these weights" from the history row.
    emit weightsPanelOf(window)->weightsCommitted({0.7, 0.1, 0.1, 0.1});
    test::windowPart<widgets::HistoryView>(window)->selectRow(0);
    QVERIFY(test::windowPart<widgets::HistoryView>(window)->applyButton()->isEnabled());
    test::windowPart<widgets::HistoryView>(window)->applyButton()->click();
    for (int i = 0; i < 4; ++i) QCOMPARE_LE(std::abs(weightAt(window, i) - row.weights[i]), 1e-12);
  }

  // Module VI reported by the operator: the point moves within 2 % of the Smith-Tlusty speed and the
  // re-selected point is recorded with source "feedback".
  void reportedChatterMovesToSmithTlustySpeed() {
    QTemporaryDir dir;
    gui::MainWindow window;
    QVERIFY(test::openParetoCase(window));
    test::paretoOf(window)->setLearningDatabasePath(dir.filePath("learning.sqlite"));
    test::paretoOf(window)->moveToChoice();
    const double n0 = window.document()->point().speed_rpm;
    test::paretoOf(window)->reportChatter(668.0);
    const double n1 = window.document()->point().speed_rpm;
    // N_s = 60 f / (n_t k) for the k nearest n0 (3 teeth)
    const double k = std::round(60.0 * 668.0 / (3.0 * n0));
    double best = 0.0;
    for (double kk : {k - 1, k, k + 1})
      if (kk >= 1 && (best == 0.0 || std::abs(60.0 * 668.0 / (3.0 * kk) - n0) < std::abs(best - n0)))
        best = 60.0 * 668.0 / (3.0 * kk);
    QCOMPARE_LE(std::abs(n1 - best), 0.02 * best + 1e-9);
    QVERIFY(test::waitForLearning(window));
    QCOMPARE(test::windowPart<widgets::HistoryView>(window)->rows().size(), 1);
    QCOMPARE(test::windowPart<widgets::HistoryView>(window)->rows().front().source, QString("feedback"));
  }

  // A point on the speed axis (a drag below it stops at b = 0) or beside the lobes (the chart reaches
  // past them) has no Pareto objectives: the monitoring dock shows none, where their robustness threw
  // out of the event loop and ended the program.
  void pointWithoutObjectives_data() {
    QTest::addColumn<double>("speed_rpm");
    QTest::addColumn<double>("depth_mm");
    QTest::newRow("no depth") << 0.0 << 0.0;
    QTest::newRow("below the lobes' speeds") << 781.141 << -1.0;
    QTest::newRow("above them") << 1e5 << -1.0;
  }
  void pointWithoutObjectives() {
    QFETCH(double, speed_rpm);
    QFETCH(double, depth_mm);
    gui::MainWindow window;
    QVERIFY(test::openParetoCase(window));
    test::contextOf(window)->setActiveTool(test::paretoOf(window)->runner()->study()->request().tool);
    widgets::MonitoringPanel* m = test::windowPart<widgets::MonitoringPanel>(window);
    QVERIFY(m->valueText("ros") != QString::fromUtf8("\u2013"));
    app::PickedPoint pt = window.document()->point();
    if (speed_rpm > 0.0) pt.speed_rpm = speed_rpm;
    if (depth_mm >= 0.0) pt.depth_mm = depth_mm;
    window.document()->setPoint(pt);
    QVERIFY(test::waitForReadout(window));
    QTest::qWait(50);
    QCOMPARE(m->valueText("ros"), QString::fromUtf8("\u2013"));
  }

  void monitoringShowsSimulationSignals() {
    gui::MainWindow window;
    QVERIFY(test::openParetoCase(window));
    QSignalSpy finished(test::simulationOf(window), &gui::SimulationFeature::simulationShown);
    test::simulationOf(window)->start();
    QVERIFY(finished.wait(60000));
    widgets::MonitoringPanel* m = test::windowPart<widgets::MonitoringPanel>(window);
    for (const char* key : {"eta", "chip_ratio", "peak_force_n", "tooth_passing_hz", "tol_min", "mrr_cm3_s"})
      QVERIFY2(m->valueText(key) != QString::fromUtf8("\u2013"), key);
    QVERIFY(m->peakTable()->rowCount() >= 1);
    QVERIFY(m->peakTable()->item(0, 2)->text().contains("tooth passing"));
  }
};

MX_REGISTER_TEST(TestParetoFeature)
#include "test_pareto_feature.moc"
