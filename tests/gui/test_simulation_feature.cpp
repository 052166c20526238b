// The live simulation in the main window (offscreen): whatever changes its point or its tool (a point
// set as a Pareto pick sets it, an undo, a tool edit, Add tool) greys the shown run as stale at once and
// re-runs it for the new state; the readout shows the run beside the lobes' verdict, marginal near the
// border; a chatter run's suggestion is checked on the lobes before it is offered, and moving there
// gives a point the lobes call stable. A run overtaken by a move is not shown as the new point's.
#include <QPushButton>
#include <QSignalSpy>
#include <QThreadPool>
#include <QUndoStack>
#include <cmath>

#include "main_window.h"
#include "simulation_view.h"
#include "support/project_files.h"
#include "support/window_features.h"
#include "test_registry.h"
#include "tool_library_editor.h"

using namespace mx;

namespace {

// Opens the project, waits for the lobes and the first simulation.
bool openAndSimulate(gui::MainWindow& window) {
  window.setQuiet(true);
  window.resize(1600, 950);
  window.show();
  QSignalSpy shown(test::simulationOf(window), &gui::SimulationFeature::simulationShown);
  return window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")) && shown.wait(30000);
}

// Sets the point as a Pareto pick or a typed feed does: not through a drag of the chart.
bool moveAndWaitForTheRun(gui::MainWindow& window, double speed_rpm, double depth_mm) {
  app::PickedPoint p = window.document()->point();
  p.speed_rpm = speed_rpm;
  p.depth_mm = depth_mm;
  QSignalSpy shown(test::simulationOf(window), &gui::SimulationFeature::simulationShown);
  window.document()->setPoint(p);
  return shown.wait(30000) && test::waitForReadout(window);
}

const gui::SimulationSummary* shownRun(const gui::MainWindow& window) {
  return test::contextOf(window)->currentSimulation();
}
}  // namespace

class TestSimulationFeature : public QObject {
  Q_OBJECT
 private slots:
  void aPointSetElsewhereGreysThenReRuns() {
    gui::MainWindow window;
    QVERIFY(openAndSimulate(window));
    widgets::SimulationView* view = test::simulationOf(window)->view();
    QVERIFY(!view->isStale());
    app::PickedPoint p = window.document()->point();
    p.speed_rpm = 1460.0;
    QSignalSpy shown(test::simulationOf(window), &gui::SimulationFeature::simulationShown);
    window.document()->setPoint(p);
    QVERIFY(view->isStale());  // at once, before any run
    QVERIFY2(view->statusText().contains("the point moved"), qPrintable(view->statusText()));
    QVERIFY(!shownRun(window));  // no feature reads the old run as this point's
    QVERIFY(shown.wait(30000));
    QVERIFY(!view->isStale());
    QVERIFY(shownRun(window));
    QCOMPARE(shownRun(window)->spindle_rpm, 1460.0);
    // Undo moves the point back: stale again, then the run of the old point.
    window.document()->undoStack()->undo();
    QVERIFY(view->isStale());
    QVERIFY(shown.wait(30000));
    QVERIFY(shownRun(window));
    QCOMPARE(shownRun(window)->spindle_rpm, window.document()->point().speed_rpm);
  }

  // A run that ends after the point moved is not shown as the point's: its result waits, already
  // computed, behind the move, and the first run shown is the one of the new point.
  void aRunOvertakenByAMoveIsNotShown() {
    gui::MainWindow window;
    QVERIFY(openAndSimulate(window));
    widgets::SimulationView* view = test::simulationOf(window)->view();
    const double old_rpm = window.document()->point().speed_rpm;
    emit test::contextOf(window)->simulationRequested();
    QVERIFY(test::contextOf(window)->enginePool()->waitForDone(30000));  // its end is queued, not yet shown
    app::PickedPoint p = window.document()->point();
    p.speed_rpm = old_rpm + 250.0;
    QSignalSpy shown(test::simulationOf(window), &gui::SimulationFeature::simulationShown);
    window.document()->setPoint(p);
    QVERIFY(shown.wait(30000));
    QVERIFY(!view->isStale());
    QVERIFY(shownRun(window));
    QCOMPARE(shownRun(window)->spindle_rpm, p.speed_rpm);
    QCOMPARE(shown.count(), 1);
  }

  void aToolEditReRunsWithTheNewTool() {
    gui::MainWindow window;
    QVERIFY(openAndSimulate(window));
    QCOMPARE(test::contextOf(window)->activeTool(), QString("R1"));
    app::Project edited = *window.project();
    edited.tools[0].teeth = 99;
    QSignalSpy shown(test::simulationOf(window), &gui::SimulationFeature::simulationShown);
    QCOMPARE(window.document()->applyEdit(edited, "teeth"), QString());
    QVERIFY(!shownRun(window));  // the 3-tooth run is no longer this project's
    QVERIFY(shown.wait(30000));
    QVERIFY(shownRun(window));
    QCOMPARE(shownRun(window)->teeth, 99);
  }

  void addToolReplacesTheOldToolsRun() {
    gui::MainWindow window;
    QVERIFY(openAndSimulate(window));
    QSignalSpy shown(test::simulationOf(window), &gui::SimulationFeature::simulationShown);
    test::editorsOf(window)->toolEditor()->addTool();
    QTRY_COMPARE(test::contextOf(window)->activeTool(), QString("T1"));
    QVERIFY(!shownRun(window));
    QVERIFY(shown.wait(30000));
    QVERIFY(shownRun(window));
    QCOMPARE(shownRun(window)->teeth, 2);  // the new tool's
  }

  // 3995 rpm, 1.007 mm: above alpha b_lim (0.943 mm) but within 5 % of the lobe: marginal, with the
  // simulation's own verdict beside it; the CLI's "verdict" agrees.
  void theBorderIsMarginal() {
    gui::MainWindow window;
    QVERIFY(openAndSimulate(window));
    QVERIFY(moveAndWaitForTheRun(window, 3995.0, 1.007));
    const widgets::OperatingPointReadout* readout = test::lobesOf(window)->readout();
    QVERIFY2(readout->text("verdict").startsWith("MARGINAL"), qPrintable(readout->text("verdict")));
    QVERIFY(readout->readout().marginal);
    const gui::SimulationSummary* run = shownRun(window);
    QVERIFY(run);
    QVERIFY2(readout->text("simulation").startsWith(run->chatter ? "CHATTER" : "STABLE"),
             qPrintable(readout->text("simulation")));
    QVERIFY(readout->text("simulation").contains(QString::number(run->eta, 'f', 3)));
  }

  // A chattering run's suggestion is checked on the lobes: at 1.206 mm the peak of the nearest pocket
  // that is stable at that depth; at 5 mm, above every lobe of the range, no speed but the deepest
  // stable depth at the nearest pocket. Moving there, the lobes say stable, and the point is simulated.
  void theSuggestionIsStableOnTheLobes_data() {
    QTest::addColumn<double>("depth_mm");
    QTest::addColumn<QString>("note");
    QTest::addColumn<bool>("shallower");
    QTest::newRow("a stable speed at this depth") << 1.206 << "No Smith-Tlusty speed is stable at 1.206 mm" << false;
    QTest::newRow("above every lobe") << 5.0 << "No speed in" << true;
  }
  void theSuggestionIsStableOnTheLobes() {
    QFETCH(double, depth_mm);
    QFETCH(QString, note);
    QFETCH(bool, shallower);
    gui::MainWindow window;
    QVERIFY(openAndSimulate(window));
    QVERIFY(moveAndWaitForTheRun(window, 3264.0, depth_mm));
    const gui::SimulationSummary* run = shownRun(window);
    QVERIFY(run && run->chatter && run->suggested_rpm);
    widgets::SimulationView* view = test::simulationOf(window)->view();
    QVERIFY2(view->suggestionNote().startsWith(note), qPrintable(view->suggestionNote()));
    QCOMPARE(run->suggested_depth_mm.has_value(), shallower);
    const double speed = *run->suggested_rpm, depth = run->suggested_depth_mm.value_or(depth_mm);
    QVERIFY(depth <= depth_mm);
    QSignalSpy shown(test::simulationOf(window), &gui::SimulationFeature::simulationShown);
    QTest::mouseClick(view->findChild<QPushButton*>("moveToSpeedButton"), Qt::LeftButton);
    QCOMPARE(window.document()->point().speed_rpm, speed);
    QCOMPARE(window.document()->point().depth_mm, depth);
    QVERIFY(test::waitForReadout(window));
    const widgets::PointReadout& r = test::lobesOf(window)->readout()->readout();
    QVERIFY(r.valid && r.stable);
    QVERIFY(shown.count() > 0 || shown.wait(30000));
  }
};

MX_REGISTER_TEST(TestSimulationFeature)
#include "test_simulation_feature.moc"
