// The main window hosts its features: each is a child found by object name; an edit a feature
// requests is one undoable document edit (the edits of one gesture of one feature merge into one
// step), a refused edit changes nothing, and a feature's status text reaches the status bar.
#include <QStatusBar>
#include <QUndoStack>

#include "control_feature.h"
#include "machining_feature.h"
#include "main_window.h"
#include "supervisor_feature.h"
#include "test_registry.h"

using namespace mx;

namespace {
app::Project withBeta(const app::Project& p, double beta) {
  app::Project edited = p;
  edited.control->beta = beta;
  return edited;
}
}  // namespace

class TestWindowFeatures : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-test");
  }

  void featuresAreFoundByName() {
    gui::MainWindow window;
    QVERIFY(window.findChild<gui::ControlFeature*>("controlFeature"));
    QVERIFY(window.findChild<gui::MachiningFeature*>("machiningFeature"));
    QVERIFY(window.findChild<gui::SupervisorFeature*>("supervisorFeature"));
    QCOMPARE(window.findChildren<gui::WindowFeature*>().size(), 3);
  }

  void featureEditsAreUndoSteps() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    QVERIFY(window.openProject(MX_PROJECTS_DIR "/rubio2006-adaptive-control.mxproj"));
    auto* control = window.findChild<gui::ControlFeature*>("controlFeature");
    auto* supervisor = window.findChild<gui::SupervisorFeature*>("supervisorFeature");
    QUndoStack* undo = window.document()->undoStack();
    const int steps = undo->count();

    // Two edits of one gesture: one step.
    emit control->editRequested(withBeta(*window.project(), 0.2), "beta", 7);
    emit control->editRequested(withBeta(*window.project(), 0.25), "beta", 7);
    QCOMPARE(undo->count(), steps + 1);
    QCOMPARE(*window.project()->control->beta, 0.25);
    // No gesture: its own step; the same gesture id from another feature: its own step too.
    emit control->editRequested(withBeta(*window.project(), 0.3), "beta", 0);
    QCOMPARE(undo->count(), steps + 2);
    emit supervisor->editRequested(withBeta(*window.project(), 0.35), "beta", 7);
    QCOMPARE(undo->count(), steps + 3);
    undo->undo();
    QCOMPARE(*window.project()->control->beta, 0.3);

    // Refused (beta outside [-1, 1]): no step, the project unchanged, the reason in the status bar.
    emit control->editRequested(withBeta(*window.project(), 2.0), "Change beta", 0);
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
