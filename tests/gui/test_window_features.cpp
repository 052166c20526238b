// The main window hosts its features: each is a child found by object name, in the order it takes
// project changes, with its docks; an edit a feature requests is one undoable document edit (the
// edits of one gesture of one feature merge into one step), so are point moves and an edit with a
// point move; a refused edit changes nothing; a feature's status text reaches the status bar.
#include <QDockWidget>
#include <QStatusBar>
#include <QUndoStack>

#include "control_feature.h"
#include "machining_feature.h"
#include "main_window.h"
#include "supervisor_feature.h"
#include "support/project_edits.h"
#include "support/project_files.h"
#include "support/window_features.h"
#include "test_registry.h"

using namespace mx;

class TestWindowFeatures : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-test");
  }

  // Every feature is reached by its object name, in the order it takes project changes, and owns
  // its docks; the window itself holds no view of a feature.
  void featuresAreFoundByNameWithTheirDocks() {
    gui::MainWindow window;
    const QStringList features{"lobesFeature",      "editorsFeature", "simulationFeature", "tapTestFeature",
                               "expertFeature",     "paretoFeature",  "controlFeature",    "machiningFeature",
                               "supervisorFeature", "batchFeature",   "helpFeature"};
    QStringList found;
    for (const auto* f : window.findChildren<gui::WindowFeature*>(Qt::FindDirectChildrenOnly)) found << f->objectName();
    QCOMPARE(found, features);
    QSet<QString> docks;
    for (const auto* d : window.findChildren<QDockWidget*>()) docks.insert(d->objectName());
    for (const char* name :
         {"pointDock", "toolsDock", "machineDock", "simulationDock", "tapTestDock", "weightsDock", "rankingDock",
          "paretoWeightsDock", "operatorRulesDock", "paretoFrontDock", "monitoringDock", "historyDock", "controlDock",
          "surfaceFinishDock", "partProgramDock", "supervisorDock"})
      QVERIFY2(docks.contains(name), name);
    QCOMPARE(window.centralWidget(), test::lobesOf(window)->chart());
  }

  // A point move a feature requests is an undo step of its own; an edit with a point move is one.
  void pointRequestsAreUndoSteps() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-adaptive-control.mxproj")));
    auto* lobes = test::lobesOf(window);
    QUndoStack* undo = window.document()->undoStack();
    window.document()->initPoint({8000.0, 1.0, 0.1});
    const int steps = undo->count();
    emit lobes->pointRequested({8100.0, 1.1, 0.1}, 3);
    emit lobes->pointRequested({8200.0, 1.2, 0.1}, 3);  // the same drag: merged
    QCOMPARE(undo->count(), steps + 1);
    QCOMPARE(window.document()->point().speed_rpm, 8200.0);
    emit lobes->editWithPointRequested(test::withBeta(*window.project(), 0.45), {9000.0, 2.0, 0.1}, "beta and point");
    QCOMPARE(undo->count(), steps + 2);
    undo->undo();
    QCOMPARE(window.document()->point().speed_rpm, 8200.0);
    QCOMPARE(*window.project()->control->beta, -0.3);
    // Refused: no step, the point stays, the reason in the status bar.
    emit lobes->editWithPointRequested(test::withBeta(*window.project(), 3.0), {9500.0, 2.0, 0.1}, "Bad beta");
    QCOMPARE(undo->index(), steps + 1);
    QVERIFY(undo->canRedo());  // the undone step is still there: nothing was pushed
    QCOMPARE(window.document()->point().speed_rpm, 8200.0);
    QVERIFY2(window.statusBar()->currentMessage().startsWith("Bad beta: "),
             qPrintable(window.statusBar()->currentMessage()));
  }

  void featureEditsAreUndoSteps() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-adaptive-control.mxproj")));
    auto* control = window.findChild<gui::ControlFeature*>("controlFeature");
    auto* supervisor = window.findChild<gui::SupervisorFeature*>("supervisorFeature");
    QUndoStack* undo = window.document()->undoStack();
    const int steps = undo->count();

    // Two edits of one gesture: one step.
    emit control->editRequested(test::withBeta(*window.project(), 0.2), "beta", 7);
    emit control->editRequested(test::withBeta(*window.project(), 0.25), "beta", 7);
    QCOMPARE(undo->count(), steps + 1);
    QCOMPARE(*window.project()->control->beta, 0.25);
    // No gesture: its own step; the same gesture id from another feature: its own step too.
    emit control->editRequested(test::withBeta(*window.project(), 0.3), "beta", 0);
    QCOMPARE(undo->count(), steps + 2);
    emit supervisor->editRequested(test::withBeta(*window.project(), 0.35), "beta", 7);
    QCOMPARE(undo->count(), steps + 3);
    undo->undo();
    QCOMPARE(*window.project()->control->beta, 0.3);

    // Refused (beta outside [-1, 1]): no step, the project unchanged, the reason in the status bar.
    emit control->editRequested(test::withBeta(*window.project(), 2.0), "Change beta", 0);
    QCOMPARE(undo->count(), steps + 3);
    QCOMPARE(*window.project()->control->beta, 0.3);
    QVERIFY2(window.statusBar()->currentMessage().startsWith("Change beta: "),
             qPrintable(window.statusBar()->currentMessage()));
  }

  void statusTextReachesTheStatusBar() {
    gui::MainWindow window;
    auto* control = window.findChild<gui::ControlFeature*>("controlFeature");
    emit control->statusMessage("sweep written", 5000);
    QCOMPARE(window.statusBar()->currentMessage(), QString("sweep written"));
  }
};

MX_REGISTER_TEST(TestWindowFeatures)
#include "test_window_features.moc"
