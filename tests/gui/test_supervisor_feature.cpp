// The supervisor dock: the project's chart of the chosen controller is drawn; a live run
// streams F_Y and tokens and ends with the metrics of the CLI's run; the operator's feed hold injected
// during a paced run reaches the run as an operator event; Compare fills the three columns; a valid
// chart edit is one undoable project edit, an invalid one is shown inline and changes nothing; module L's
// time constant and restart mode are shown from the project, each change is one undo step that the next
// run takes, and a value out of range is refused with the document's message.
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>

#include "document/project.h"
#include "grafcet_chart_editor.h"
#include "grafcet_chart_view.h"
#include "main_window.h"
#include "supervision_runner.h"
#include "supervision_timeline.h"
#include "supervisor_comparison.h"
#include "supervisor_feature.h"
#include "supervisor_view.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx;

namespace {
bool openLanders(gui::MainWindow& w) {
  w.setQuiet(true);
  w.resize(1600, 950);
  w.show();
  return w.openProject(mx::test::exampleCopy("landers-face-milling.mxproj"));
}

gui::SupervisorFeature* supervisor(const gui::MainWindow& w) {
  return w.findChild<gui::SupervisorFeature*>("supervisorFeature");
}

QJsonObject modelControllerOf(const gui::MainWindow& w) {
  return app::projectToJson(*w.project()).value("supervisor").toObject().value("model_controller").toObject();
}

// The Landers project with supervisor.model_controller replaced (left out when empty), in `dir`.
QString landersWith(const QTemporaryDir& dir, const QJsonObject& model_controller) {
  QFile in(MX_PROJECTS_DIR "/landers-face-milling.mxproj");
  if (!in.open(QIODevice::ReadOnly)) return {};
  QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
  QJsonObject section = root.value("supervisor").toObject();
  section.remove("model_controller");
  if (!model_controller.isEmpty()) section.insert("model_controller", model_controller);
  root.insert("supervisor", section);
  QString path = dir.filePath("landers.mxproj");
  QFile out(path);
  if (!out.open(QIODevice::WriteOnly) || out.write(QJsonDocument(root).toJson()) < 0) return {};
  return path;
}

// The settling time [s] of the first force transient of the next finished run (-1: never settled).
double nextFirstSettling(QSignalSpy& finished) {
  finished.clear();
  if (!finished.wait(120000)) return -2.0;
  const auto outcome = qvariant_cast<gui::SupervisionOutcome>(finished.at(0).at(0));
  if (!outcome.result || outcome.result->metrics.force_transients.empty()) return -3.0;
  return outcome.result->metrics.force_transients.front().settling_s;
}
}  // namespace

class TestSupervisorFeature : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-test");
  }

  // A project with a supervisor section says so from the start, before any run; one without says it has none.
  void statusAtStartupNamesTheSection() {
    gui::MainWindow window;
    QVERIFY(openLanders(window));
    widgets::SupervisorView* view = supervisor(window)->view();
    QVERIFY(view->isEnabled());
    QVERIFY2(view->statusText().startsWith("Supervisor ready (controller " + view->controller() + ")"),
             qPrintable(view->statusText()));
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QCOMPARE(view->statusText(), QString("This project has no \"supervisor\" section (docs/project-file.md)"));
  }

  void liveRunWithFeedHold() {
    gui::MainWindow window;
    QVERIFY(openLanders(window));
    widgets::SupervisorView* view = supervisor(window)->view();
    QVERIFY(view->isEnabled());
    view->setController("smc1");
    emit view->controllerChanged("smc1");
    QCOMPARE(view->chartView()->chart().steps.size(), 5);
    // A paced run (20x): the feed hold pressed while it runs is an operator event of the run.
    view->speedCombo()->setCurrentIndex(2);
    QCOMPARE(view->speedFactor(), 20.0);
    QSignalSpy chunks(supervisor(window)->runner(), &gui::SupervisionRunner::chunkReady);
    QSignalSpy done(supervisor(window), &gui::SupervisorFeature::supervisionFinished);
    supervisor(window)->start();
    QVERIFY(chunks.wait(20000));
    emit view->feedHoldToggled(true);
    QTest::qWait(200);
    emit view->feedHoldToggled(false);
    QTest::qWait(300);                     // a few chunks (every 50 ms simulated = 2.5 ms at 20x)
    supervisor(window)->runner()->stop();  // do not wait for 43 s / 20
    QTest::qWait(300);
    QVERIFY(view->timeline()->pointCount() > 0);
    QVERIFY(!view->chartView()->activeSteps().isEmpty());
    QVERIFY(view->timeline()->eventCount() >= 1);
    bool hold_on = false, hold_off = false;
    for (const QList<QVariant>& args : chunks)
      for (const SupervisionEvent& e : qvariant_cast<gui::SupervisionChunk>(args.at(0)).events) {
        hold_on = hold_on || (e.type == "operator" && e.detail == "feed hold on");
        hold_off = hold_off || (e.type == "operator" && e.detail == "feed hold off");
      }
    QVERIFY(hold_on);
    QVERIFY(hold_off);

    // An unpaced run to the end gives the CLI's metrics (no chatter, two passes).
    view->speedCombo()->setCurrentIndex(3);
    QCOMPARE(view->speedFactor(), 0.0);
    supervisor(window)->start();
    QVERIFY(done.wait(120000));
    QVERIFY(view->metricsText().contains("2"));  // passes
    QVERIFY(view->timeline()->spanCount() > 0);
  }

  // The GUI keeps answering during a run as fast as possible (chunks are throttled to one per 40 ms).
  void eventLoopKeepsTickingDuringARun() {
    gui::MainWindow window;
    QVERIFY(openLanders(window));
    widgets::SupervisorView* view = supervisor(window)->view();
    view->setController("smc2");
    emit view->controllerChanged("smc2");
    view->speedCombo()->setCurrentIndex(3);  // max
    QSignalSpy done(supervisor(window), &gui::SupervisorFeature::supervisionFinished);
    QElapsedTimer clock;
    qint64 last = 0, worst = 0;
    QTimer tick;
    tick.setInterval(5);
    connect(&tick, &QTimer::timeout, [&] {
      const qint64 now = clock.elapsed();
      worst = std::max(worst, now - last);
      last = now;
    });
    clock.start();
    tick.start();
    supervisor(window)->start();
    QVERIFY(done.wait(120000));
    tick.stop();
    qInfo("largest event-loop gap during a max-speed SMC II run: %lld ms", worst);
    // The 50 ms target is measured in docs/performance.md; CI machines vary, sanitizers slow it further.
    QCOMPARE_LE(worst, qint64(250 * MX_TIMING_SCALE));
  }

  void compareFillsThreeColumns() {
    gui::MainWindow window;
    QVERIFY(openLanders(window));
    QSignalSpy results(supervisor(window), &gui::SupervisorFeature::comparisonResult);
    supervisor(window)->compare();
    for (int i = 0; i < 3 && results.count() < 3; ++i) QVERIFY(results.wait(120000));
    QCOMPARE(results.count(), 3);
    widgets::SupervisorComparison* c = supervisor(window)->view()->comparison();
    QCOMPARE(c->resultCount(), 3);
    QCOMPARE(c->metricText("none", "chatter_detected"), QString("yes"));
    QCOMPARE(c->metricText("smc1", "chatter_detected"), QString("no"));
    QCOMPARE(c->metricText("smc2", "passes"), QString("2"));
  }

  void chartEditsAreProjectEdits() {
    gui::MainWindow window;
    QVERIFY(openLanders(window));
    widgets::SupervisorView* view = supervisor(window)->view();
    view->setController("smc2");
    emit view->controllerChanged("smc2");
    widgets::GrafcetChartEditor* editor = view->editor();
    widgets::GrafcetChartData chart = editor->chart();
    QCOMPARE(chart.steps.size(), 6);
    // Valid: rename a step -> one undoable edit of supervisor.charts.smc2.
    chart.steps[1].name = "Waiting for contact";
    emit editor->chartEdited(chart);
    const auto name = [&] {
      return app::projectToJson(*window.project())
          .value("supervisor")
          .toObject()
          .value("charts")
          .toObject()
          .value("smc2")
          .toObject()
          .value("steps")
          .toArray()
          .at(1)
          .toObject()
          .value("name")
          .toString();
    };
    QCOMPARE(name(), QString("Waiting for contact"));
    window.document()->undoStack()->undo();
    QCOMPARE(name(), QString("No Contact and No Chatter"));
    // Invalid (a transition without a target): the editor lists the issue, nothing reaches the project.
    editor->setChart(chart);
    widgets::GrafcetChartData bad = chart;
    bad.transitions[0].to.clear();
    editor->setChart(bad);
    QVERIFY(!editor->issues().isEmpty());
    QCOMPARE(name(), QString("No Contact and No Chatter"));
  }

  // Each change of module L's settings is one undo step; undo and redo bring the view and the request along.
  void modelControllerEditsAreUndoSteps() {
    gui::MainWindow window;
    QVERIFY(openLanders(window));
    widgets::SupervisorView* view = supervisor(window)->view();
    QCOMPARE(view->timeConstantMs(), 200.0);
    QCOMPARE(view->resetFeed(), QString("model"));
    QUndoStack* undo = window.document()->undoStack();
    const int steps = undo->count();
    view->timeConstantSpin()->setValue(50.0);  // a committed value (keyboard tracking is off)
    QCOMPARE(undo->count(), steps + 1);
    QCOMPARE(modelControllerOf(window).value("time_constant_ms").toDouble(), 50.0);
    QCOMPARE(supervisor(window)->request()->scenario.force_time_constant_s, 0.05);
    view->resetFeedCombo()->setCurrentIndex(view->resetFeedCombo()->findData("current"));
    QCOMPARE(undo->count(), steps + 2);
    QCOMPARE(modelControllerOf(window).value("reset_feed").toString(), QString("current"));
    QCOMPARE(supervisor(window)->request()->scenario.force_reset_feed, ResetFeed::Current);

    undo->undo();
    QCOMPARE(modelControllerOf(window).value("reset_feed").toString(), QString("model"));
    QCOMPARE(view->resetFeed(), QString("model"));
    QCOMPARE(supervisor(window)->request()->scenario.force_reset_feed, ResetFeed::Model);
    undo->undo();
    QCOMPARE(modelControllerOf(window).value("time_constant_ms").toDouble(), 200.0);
    QCOMPARE(view->timeConstantMs(), 200.0);
    QCOMPARE(supervisor(window)->request()->scenario.force_time_constant_s, 0.2);
    undo->redo();
    QCOMPARE(view->timeConstantMs(), 50.0);
  }

  // The edges of [1, 1e5] ms are project edits; a value outside is refused with the document's message.
  void timeConstantEdges_data() {
    QTest::addColumn<double>("ms");
    QTest::addColumn<QString>("error");
    QTest::newRow("1 ms") << 1.0 << QString();
    QTest::newRow("100000 ms") << 1e5 << QString();
    QTest::newRow("0.5 ms refused") << 0.5 << "supervisor.model_controller.time_constant_ms = 0.5: must be in [1, 1e5]";
    QTest::newRow("100001 ms refused") << 100001.0
                                       << "supervisor.model_controller.time_constant_ms = 100001: must be in [1, 1e5]";
  }
  void timeConstantEdges() {
    QFETCH(double, ms);
    QFETCH(QString, error);
    gui::MainWindow window;
    QVERIFY(openLanders(window));
    widgets::SupervisorView* view = supervisor(window)->view();
    QSignalSpy errors(supervisor(window), &gui::SupervisorFeature::errorRaised);
    const int steps = window.document()->undoStack()->count();
    emit view->timeConstantEdited(ms);
    if (error.isEmpty()) {
      QCOMPARE(errors.count(), 0);
      QCOMPARE(window.document()->undoStack()->count(), steps + 1);
      QCOMPARE(modelControllerOf(window).value("time_constant_ms").toDouble(), ms);
      QCOMPARE(supervisor(window)->request()->scenario.force_time_constant_s, ms * 1e-3);
      return;
    }
    QCOMPARE(errors.count(), 1);
    QCOMPARE(errors.at(0).at(1).toString(), error);
    QCOMPARE(window.document()->undoStack()->count(), steps);
    QCOMPARE(modelControllerOf(window).value("time_constant_ms").toDouble(), 200.0);
    QCOMPARE(view->timeConstantMs(), 200.0);  // the view shows the project's value again
  }

  void unknownResetFeedIsRefused() {
    gui::MainWindow window;
    QVERIFY(openLanders(window));
    widgets::SupervisorView* view = supervisor(window)->view();
    QSignalSpy errors(supervisor(window), &gui::SupervisorFeature::errorRaised);
    emit view->resetFeedEdited("warm");
    QCOMPARE(errors.count(), 1);
    QCOMPARE(errors.at(0).at(1).toString(),
             QString("supervisor.model_controller.reset_feed = 'warm': must be current or model"));
    QCOMPARE(modelControllerOf(window).value("reset_feed").toString(), QString("model"));
    QCOMPARE(view->resetFeed(), QString("model"));
  }

  // A project's values are shown; a section without model_controller shows the defaults.
  void projectValuesAreShown() {
    const QTemporaryDir dir;
    QVERIFY(dir.isValid());
    gui::MainWindow window;
    window.setQuiet(true);
    widgets::SupervisorView* view = supervisor(window)->view();
    QVERIFY(window.openProject(landersWith(dir, {{"time_constant_ms", 350}, {"reset_feed", "current"}})));
    QCOMPARE(view->timeConstantMs(), 350.0);
    QCOMPARE(view->resetFeed(), QString("current"));
    QCOMPARE(supervisor(window)->request()->scenario.force_time_constant_s, 0.35);
    QCOMPARE(supervisor(window)->request()->scenario.force_reset_feed, ResetFeed::Current);
    QVERIFY(window.openProject(landersWith(dir, {})));
    QCOMPARE(view->timeConstantMs(), 200.0);
    QCOMPARE(view->resetFeed(), QString("model"));
  }

  // The run takes the project's time constant: SMC I's force settles later after contact with a longer tau.
  void timeConstantReachesTheRun() {
    gui::MainWindow window;
    QVERIFY(openLanders(window));
    widgets::SupervisorView* view = supervisor(window)->view();
    view->setController("smc1");
    emit view->controllerChanged("smc1");
    view->speedCombo()->setCurrentIndex(3);  // max
    QSignalSpy finished(supervisor(window)->runner(), &gui::SupervisionRunner::finished);
    view->timeConstantSpin()->setValue(50.0);
    supervisor(window)->start();
    const double fast = nextFirstSettling(finished);
    view->timeConstantSpin()->setValue(400.0);  // the shown run re-runs with the edited project
    const double slow = nextFirstSettling(finished);
    qInfo("first force settling after contact: %.3f s at 50 ms, %.3f s at 400 ms", fast, slow);
    QVERIFY(fast > 0.0);
    QCOMPARE_GT(slow, 3.0 * fast);
  }
};

MX_REGISTER_TEST(TestSupervisorFeature)
#include "test_supervisor_feature.moc"
