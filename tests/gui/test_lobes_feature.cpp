// The lobe chart and the operating point (offscreen main window): open, drag the operating point on
// the chart (the readouts show the engine's values), one undo step per drag, inch display, the tools
// shown on the chart, and a responsive event loop while the engine thread computes. Where a project
// opens: its stored operating point, else a sensible first point (q* with an expert section); a save
// stores the point and the active tool. Lobes that end just after an edit are dropped, not shown.
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QListWidget>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <cmath>
#include <functional>

#include "lobe_tool_panel.h"
#include "main_window.h"
#include "model/cutting_force.h"
#include "stability/stability_boundary.h"
#include "stability/zero_order_lobes.h"
#include "support/engine_hold.h"
#include "support/event_loop_probe.h"
#include "support/project_files.h"
#include "support/window_features.h"
#include "test_registry.h"

using namespace mx;

namespace {

// Shows the window (offscreen), opens `path` and waits for its lobes.
bool openAndShow(gui::MainWindow& window, const QString& path) {
  window.setQuiet(true);
  window.resize(1400, 900);
  window.show();
  QSignalSpy shown(test::lobesOf(window), &gui::LobesFeature::lobesShown);
  return window.openProject(path) && shown.wait(20000);
}

double readoutNumber(const gui::MainWindow& w, const QString& field) {
  return test::lobesOf(w)->readout()->text(field).section(' ', 0, 0).toDouble();
}

// The bundled project `name` written to `dir` with `edit` applied to its JSON.
QString editedCopy(const QTemporaryDir& dir, const QString& name, const std::function<void(QJsonObject&)>& edit) {
  QJsonObject root = test::readJson(test::projectsPath(name));
  edit(root);
  return test::writeText(dir, name, QJsonDocument(root).toJson());
}

QJsonObject pointJson(const QString& tool, double speed_rpm, double depth_mm, double feed_mm_per_tooth) {
  return {{"tool", tool}, {"speed_rpm", speed_rpm}, {"depth_mm", depth_mm}, {"feed_mm_per_tooth", feed_mm_per_tooth}};
}

std::optional<app::OperatingPointSpec> pointInFile(const QString& path) {
  return app::loadProject(path).operating_point;
}

double feedShown(const gui::MainWindow& w) {
  return test::windowPart<QDoubleSpinBox>(w, "pointFeedSpin")->value();
}
}  // namespace

class TestLobesFeature : public QObject {
  Q_OBJECT
 private slots:
  void opensProjectAndPlotsLobes() {
    gui::MainWindow window;
    window.setQuiet(true);
    QSignalSpy shown(test::lobesOf(window), &gui::LobesFeature::lobesShown);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QVERIFY(shown.wait(20000));
    QCOMPARE(window.project()->tools.size(), size_t{2});
    QVERIFY(window.windowTitle().contains("rubio2006"));
    // View > Tools on the chart hides and shows a tool's lobes.
    test::lobesOf(window)->chart()->setToolVisible("R2", false);
    QVERIFY(!test::lobesOf(window)->chart()->isToolVisible("R2"));
    test::lobesOf(window)->chart()->setToolVisible("R2", true);
    QVERIFY(test::lobesOf(window)->chart()->isToolVisible("R2"));
  }

  // Lobes that end just after an edit are of the project before it: dropped, so that the first lobes
  // shown after the edit are its own (here one tool left of two).
  void lobesOfTheProjectBeforeAnEditAreDropped() {
    gui::MainWindow window;
    window.setQuiet(true);
    QSignalSpy opened(test::lobesOf(window), &gui::LobesFeature::lobesShown);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QVERIFY(opened.wait(20000));
    app::Project edited = *window.project();
    edited.tools[0].teeth = 4;  // the lobes of 2 tools
    QCOMPARE(test::applyEditAndHoldItsResults(window, edited, [&] { return test::engineOf(window)->busy(); }),
             QString());
    edited.tools.resize(1);
    QSignalSpy shown(test::lobesOf(window), &gui::LobesFeature::lobesShown);
    QCOMPARE(window.document()->applyEdit(edited, "remove tool"), QString());
    QVERIFY(shown.wait(20000));
    QCOMPARE(test::lobesOf(window)->snapshot()->tools.size(), std::size_t{1});
  }

  // File > New after a project: no lobes and no readout of the previous project's point.
  void aNewProjectShowsNoReadoutOfTheOldOne() {
    gui::MainWindow window;
    window.setQuiet(true);
    window.document()->setAutosaveInterval(0);
    QSignalSpy shown(test::lobesOf(window), &gui::LobesFeature::lobesShown);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QVERIFY(shown.wait(20000));
    QVERIFY(test::waitForReadout(window));
    QCOMPARE(test::lobesOf(window)->readout()->text("tool"), QString("R1"));
    QAction* new_project = nullptr;
    for (QAction* a : window.findChildren<QAction*>())
      if (a->text() == "&New project") new_project = a;
    QVERIFY(new_project);
    new_project->trigger();
    QVERIFY(window.project()->tools.empty());
    QTest::qWait(200);  // any readout still on its way from the old project
    QCOMPARE(test::lobesOf(window)->readout()->text("tool"), QString("\u2014"));
    QVERIFY2(test::lobesOf(window)->readout()->text("verdict").contains("No tool"),
             qPrintable(test::lobesOf(window)->readout()->text("verdict")));
    QVERIFY(test::lobesOf(window)->chart()->toolPanel()->toolList()->count() == 0);
  }

  // A press / move / release drag on the chart moves the point; the readouts equal an independent
  // engine evaluation (ZOA lobes of the project's tool, StabilityBoundary, evaluateCut).
  void dragMovesPointAndReadoutsMatchEngine() {
    gui::MainWindow window;
    QVERIFY(openAndShow(window, mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    widgets::LobeChartView* chart = test::lobesOf(window)->chart();
    QWidget* plot = chart->plotWidget();
    const QPoint from = chart->pixelFor(2500.0, 0.30), to = chart->pixelFor(4200.0, 0.45);
    QTest::mousePress(plot, Qt::LeftButton, Qt::NoModifier, from);
    QTest::mouseMove(plot, (from + to) / 2);
    const double mid_speed = window.document()->point().speed_rpm;
    QVERIFY(mid_speed > 2600.0 && mid_speed < 4100.0);  // the readouts follow during the drag
    QTest::mouseMove(plot, to);
    QTest::mouseRelease(plot, Qt::LeftButton, Qt::NoModifier, to);
    const app::PickedPoint p = window.document()->point();
    QVERIFY2(std::abs(p.speed_rpm - 4200.0) < 30.0, qPrintable(QString::number(p.speed_rpm)));
    QVERIFY2(std::abs(p.depth_mm - 0.45) < 0.01, qPrintable(QString::number(p.depth_mm)));
    QVERIFY(test::waitForReadout(window));

    const app::Project& project = *window.project();
    const MillingSetup setup = project.setupFor("R1");
    const auto& grid = *project.expert->grid;
    const auto speeds =
        SpeedGrid{rpmToRevPerS(grid.speed_from_rpm), rpmToRevPerS(grid.speed_to_rpm), rpmToRevPerS(10.0)}.values();
    ZoaOptions o;
    o.delta_per_s = project.expert->delta_per_s;
    const StabilityBoundary boundary(computeZoaLobes(setup, speeds, o), project.expert->alpha);
    const double n = rpmToRevPerS(p.speed_rpm), b = p.depth_mm * 1e-3;
    const CutPerformance perf = evaluateCut(setup, {n, b, p.feed_mm_per_tooth * 1e-3});
    QCOMPARE_LE(std::abs(readoutNumber(window, "blim") - boundary.depthLimit(n) * 1e3), 1e-4);
    QCOMPARE_LE(std::abs(readoutNumber(window, "power") - perf.peak_power_w), 0.05);
    QCOMPARE_LE(std::abs(readoutNumber(window, "dns") - revPerSToRpm(boundary.speedSecurity(n, b))), 0.5);
    QCOMPARE_LE(std::abs(readoutNumber(window, "mrr") - perf.mrr_m3_per_s * 6e7), 0.005);  // cm³/min
    QCOMPARE(test::lobesOf(window)->readout()->text("verdict").startsWith("STABLE"),
             boundary.isStable(n, b) && perf.peak_power_w <= 745.3);

    // The whole drag is one undo step.
    window.document()->undoStack()->undo();
    QVERIFY(std::abs(window.document()->point().speed_rpm - 4200.0) > 30.0);
  }

  // The readout's peak force against the tool's F_allow (Rule 3): a max_force_N edit below the point's
  // force turns a stable verdict into "tool force limit exceeded" at once, without new lobes; undo
  // restores it.
  void toolForceLimitInTheReadout() {
    gui::MainWindow window;
    QVERIFY(openAndShow(window, mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    app::PickedPoint p = window.document()->point();
    p.speed_rpm = 3000.0;
    p.depth_mm = 0.2;
    p.feed_mm_per_tooth = 0.1;
    window.document()->setPoint(p);
    QVERIFY(test::waitForReadout(window));
    const MillingSetup setup = window.project()->setupFor("R1");
    const double force = evaluateCut(setup, {rpmToRevPerS(3000.0), 0.2e-3, 0.1e-3}).peak_force_n;
    QCOMPARE_LE(std::abs(readoutNumber(window, "force") - force), 0.05);
    const gui::LobesFeature* lobes = test::lobesOf(window);
    QCOMPARE(lobes->readout()->text("force_fraction"), QString("no tool force limit"));
    QVERIFY(lobes->readout()->text("verdict").startsWith("STABLE"));
    app::Project edited = *window.project();
    edited.tools[0].max_force_N = 0.5 * force;
    QCOMPARE(window.document()->applyEdit(edited, "F_allow"), QString());
    QTRY_VERIFY(lobes->readout()->text("verdict").contains("tool force limit exceeded"));
    QVERIFY2(lobes->readout()->text("force_fraction").startsWith("200.0 % of"),
             qPrintable(lobes->readout()->text("force_fraction")));
    window.document()->undoStack()->undo();
    QTRY_VERIFY(lobes->readout()->text("verdict").startsWith("STABLE"));
  }

  // The chart names the model of the active tool's lobes; the method advice follows the tool and the method.
  void modelLabelAndMethodAdvice() {
    gui::MainWindow window;
    QVERIFY(openAndShow(window, mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    gui::LobesFeature* lobes = test::lobesOf(window);
    QCOMPARE(lobes->chart()->modelLabel(), QString("Tool R1: ZOA, 3 teeth, uniform pitch"));
    QCOMPARE(lobes->methodAdviceText(), QString());  // R1: a/D = 1, straight teeth, uniform pitch
    app::Project edited = *window.project();
    edited.tools[0].pitch_deg = std::vector<double>{100, 130, 130};
    QSignalSpy shown(lobes, &gui::LobesFeature::lobesShown);
    QCOMPARE(window.document()->applyEdit(edited, "pitch"), QString());
    QCOMPARE(lobes->methodAdviceText(),
             QString("ZOA: approximate for this tool (variable pitch); SDM models pitch, helix and process damping"));
    QVERIFY(shown.wait(20000));
    QCOMPARE(lobes->chart()->modelLabel(), QString("Tool R1: ZOA, 3 teeth, variable pitch"));
    lobes->setMethod(gui::LobeMethod::SemiDiscretization);
    QCOMPARE(lobes->methodAdviceText(), QString());
    test::engineOf(window)->cancelAll();
  }

  // Inch display: the chart and readouts convert; the document stays in mm.
  void inchUnitsOnChartAndReadouts() {
    gui::MainWindow window;
    QVERIFY(openAndShow(window, mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    window.units()->setLength(widgets::DisplayUnits::Length::Inch);
    QWidget* plot = test::lobesOf(window)->chart()->plotWidget();
    const QPoint at = test::lobesOf(window)->chart()->pixelFor(4000.0, 0.5);
    QTest::mousePress(plot, Qt::LeftButton, Qt::NoModifier, at);
    QTest::mouseRelease(plot, Qt::LeftButton, Qt::NoModifier, at);
    QVERIFY(std::abs(window.document()->point().depth_mm - 0.5) < 0.01);
    QVERIFY(test::waitForReadout(window));
    QVERIFY(test::lobesOf(window)->readout()->text("depth").endsWith(" in"));
    QCOMPARE_LE(std::abs(readoutNumber(window, "depth") - window.document()->point().depth_mm / 25.4), 1e-5);
  }

  // The largest cutter the project allows (100 teeth, 60 deg helix, runout): its static cut spans a
  // revolution, about 0.2 s per readout (bench BM_EvaluateCutHundredTeeth), on the readout thread.
  // A burst of point moves keeps the GUI's event loop within 50 ms, and the readouts end on the last
  // point with the engine's values.
  void aHundredToothCutterKeepsTheEventLoopResponsive() {
    gui::MainWindow window;
    QVERIFY(openAndShow(window, mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    app::Project edited = *window.project();
    app::ToolSpec& t = edited.tools[0];
    t.teeth = 100;
    t.diameter_mm = 100.0;
    t.helix_deg = 60.0;
    t.runout_um = std::vector<double>(100);
    for (int j = 0; j < 100; ++j) (*t.runout_um)[std::size_t(j)] = (j % 5) * 2.0;
    edited.tools.resize(1);
    edited.expert->grid->depth_divisions = 2;  // a small expert session: its Rule 5 runs are not this test's
    QSignalSpy shown(test::lobesOf(window), &gui::LobesFeature::lobesShown);
    QCOMPARE(window.document()->applyEdit(edited, "a 100-tooth face mill"), QString());
    QVERIFY(shown.wait(60000));
    // Twenty moves 20 ms apart, each from a timer event as a drag's are from input events.
    app::PickedPoint p = window.document()->point();
    int moves = 0;
    QTimer mover;
    mover.setInterval(20);
    connect(&mover, &QTimer::timeout, this, [&] {
      p.speed_rpm = 2000.0 + 50.0 * moves;
      p.depth_mm = 1.0 + 0.05 * moves;
      window.document()->setPoint(p);
      if (++moves == 20) mover.stop();
    });
    QElapsedTimer clock;
    clock.start();
    test::EventLoopProbe probe;
    mover.start();
    QTRY_VERIFY_WITH_TIMEOUT(moves == 20 && test::lobesOf(window)->readoutIsCurrent(), 60000);
    qInfo("100-tooth cutter: 20 moves, readouts current after %lld ms; longest event %lld ms (%s)", clock.elapsed(),
          probe.longestMs(), qPrintable(probe.longestEvent()));
    QCOMPARE_LE(probe.longestMs(), qint64(50 * MX_TIMING_SCALE));
    const CutPerformance perf = evaluateCut(window.project()->setupFor("R1"),
                                            {rpmToRevPerS(p.speed_rpm), p.depth_mm * 1e-3, p.feed_mm_per_tooth * 1e-3});
    const widgets::PointReadout& r = test::lobesOf(window)->readout()->readout();
    QCOMPARE(r.speed_rpm, p.speed_rpm);
    QCOMPARE_LE(std::abs(r.peak_power_w - perf.peak_power_w), 1e-9 * perf.peak_power_w);
  }

  // While the engine thread computes semi-discretization lobes of 200 speeds, the GUI event loop
  // keeps ticking (the largest gap is a benchmark figure, docs/performance.md; not gated here).
  void eventLoopKeepsTickingDuringSdm() {
    gui::MainWindow window;
    window.setQuiet(true);
    QSignalSpy shown(test::lobesOf(window), &gui::LobesFeature::lobesShown);
    QVERIFY(window.openProject(mx::test::exampleCopy("rubio2006-tool-selection.mxproj")));
    QVERIFY(shown.wait(20000));
    QElapsedTimer clock;
    qint64 last = 0, largest_gap = 0;
    int ticks = 0;
    QTimer timer;
    timer.setInterval(5);
    connect(&timer, &QTimer::timeout, this, [&] {
      const qint64 now = clock.elapsed();
      largest_gap = std::max(largest_gap, now - last);
      last = now;
      ++ticks;
    });
    QSignalSpy busy(test::engineOf(window), &gui::EngineRunner::busyChanged);
    clock.start();
    timer.start();
    test::lobesOf(window)->setMethod(gui::LobeMethod::SemiDiscretization);
    // Watch the loop until the job ends, or for 3 s (sanitizer builds are far slower).
    const bool finished = shown.wait(3000) || shown.count() > 0;
    const qint64 elapsed = clock.elapsed();
    timer.stop();
    qInfo("SDM lobes (2 tools, 2 x 200 speeds): %s after %lld ms; %d ticks; largest gap %lld ms",
          finished ? "finished" : "still running", elapsed, ticks, largest_gap);
    QVERIFY(busy.count() >= 1);
    test::engineOf(window)->cancelAll();
    QVERIFY(ticks >= 5);
  }
  // A project with a stored operating point opens there, on its tool (not the first one): the chart's
  // marker, the feed and the readouts; the expert ranking, when it arrives, leaves it there.
  void opensAtTheStoredPoint() {
    QTemporaryDir dir;
    const QString path = editedCopy(dir, "rubio2006-tool-selection.mxproj", [](QJsonObject& root) {
      root["operating_point"] = pointJson("R2", 4000, 0.3, 0.15);
    });
    gui::MainWindow window;
    QSignalSpy ranked(test::expertOf(window), &gui::ExpertFeature::rankingShown);
    QVERIFY(openAndShow(window, path));
    QCOMPARE(test::contextOf(window)->activeTool(), QString("R2"));
    QCOMPARE(window.document()->point(), app::PickedPoint({4000.0, 0.3, 0.15}));
    QCOMPARE(test::lobesOf(window)->chart()->pointSpeed(), 4000.0);
    QCOMPARE(test::lobesOf(window)->chart()->pointDepth(), 0.3);
    QCOMPARE(feedShown(window), 0.15);
    QVERIFY(test::waitForReadout(window));
    QCOMPARE(test::contextOf(window)->readout().tool_id, QString("R2"));
    QCOMPARE(test::contextOf(window)->readout().speed_rpm, 4000.0);
    QVERIFY(ranked.wait(60000));
    QCOMPARE(window.document()->point(), app::PickedPoint({4000.0, 0.3, 0.15}));
    QCOMPARE(test::contextOf(window)->activeTool(), QString("R2"));
    QVERIFY(!window.document()->isDirty());
  }

  // Save writes the point and the active tool as operating_point; saving the reopened file again
  // changes no byte; a moved point is saved, and after its undo the point before it.
  void saveStoresThePointAndTheActiveTool() {
    QTemporaryDir dir;
    const QString path = editedCopy(dir, "rubio2006-tool-selection.mxproj", [](QJsonObject&) {});
    QByteArray saved;
    app::PickedPoint opened;
    {
      gui::MainWindow window;
      QSignalSpy ranked(test::expertOf(window), &gui::ExpertFeature::rankingShown);
      QVERIFY(openAndShow(window, path));
      QVERIFY(ranked.wait(60000));
      test::contextOf(window)->setActiveTool("R2");
      opened = window.document()->point();
      QVERIFY(opened.speed_rpm > 0.0);
      QVERIFY(window.saveProject());
      QCOMPARE(*pointInFile(path),
               (app::OperatingPointSpec{"R2", opened.speed_rpm, opened.depth_mm, opened.feed_mm_per_tooth}));
      saved = test::readBytes(path);
    }
    gui::MainWindow window;
    QSignalSpy ranked(test::expertOf(window), &gui::ExpertFeature::rankingShown);
    QVERIFY(openAndShow(window, path));
    QVERIFY(ranked.wait(60000));
    QCOMPARE(window.document()->point(), opened);
    QVERIFY(window.saveProject());
    QCOMPARE(test::readBytes(path), saved);

    window.document()->setPoint({5000.0, 0.4, 0.2});
    QVERIFY(window.document()->isDirty());
    QVERIFY(window.saveProject());
    QCOMPARE(*pointInFile(path), (app::OperatingPointSpec{"R2", 5000.0, 0.4, 0.2}));
    window.document()->undoStack()->undo();
    QVERIFY(window.saveProject());
    QCOMPARE(test::readBytes(path), saved);
  }

  // Without a stored point a project opens at a sensible cut: q* with an expert section, else the
  // first point of the lobes and the power-limit curve; stable, at least a quarter of b_lim, within the
  // spindle's power and speed. library-20-tools opened at 0.019 mm and landers-face-milling (without its
  // stored point) above the power limit and the spindle's top speed.
  void opensAtASensiblePoint_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<bool>("ranked");  // the expert section's q*
    QTest::addColumn<bool>("stored");  // keep the project's operating_point
    QTest::addColumn<double>("min_depth_mm");
    QTest::newRow("library-20-tools: q*") << "library-20-tools.mxproj" << true << true << 0.1;
    QTest::newRow("rubio2006: q*") << "rubio2006-tool-selection.mxproj" << true << true << 0.4;
    QTest::newRow("landers: first point") << "landers-face-milling.mxproj" << false << false << 0.5;
    QTest::newRow("landers: stored point") << "landers-face-milling.mxproj" << false << true << 1.0;
    QTest::newRow("cus-zuperl: first point") << "cus-zuperl-sdnrp.mxproj" << false << false << 0.5;
  }
  void opensAtASensiblePoint() {
    QFETCH(QString, name);
    QFETCH(bool, ranked);
    QFETCH(bool, stored);
    QFETCH(double, min_depth_mm);
    QTemporaryDir dir;
    const QString path = editedCopy(dir, name, [stored](QJsonObject& root) {
      if (!stored) root.remove("operating_point");
    });
    gui::MainWindow window;
    QSignalSpy ranking(test::expertOf(window), &gui::ExpertFeature::rankingShown);
    QVERIFY(openAndShow(window, path));
    if (ranked) QVERIFY(ranking.wait(60000));
    QTest::qWait(1000);  // the power-limit curve of the first point, on the readout thread
    QVERIFY(test::waitForReadout(window));
    const widgets::PointReadout& r = test::contextOf(window)->readout();
    const app::Project& p = *window.project();
    const QString where = QString("%1 rpm, %2 mm, %3 mm/tooth: b_lim %4 mm, %5 W of %6 W")
                              .arg(r.speed_rpm)
                              .arg(r.depth_mm)
                              .arg(r.feed_mm_per_tooth)
                              .arg(r.blim_mm)
                              .arg(r.peak_power_w)
                              .arg(r.power_limit_w);
    qInfo("%s opens at %s", qPrintable(name), qPrintable(where));
    QVERIFY2(r.valid && r.stable, qPrintable(where));
    QVERIFY2(r.depth_mm >= min_depth_mm && r.depth_mm >= 0.25 * r.blim_mm, qPrintable(where));
    QVERIFY2(r.peak_power_w <= r.power_limit_w, qPrintable(where));
    QVERIFY2(r.speed_rpm <= p.machine->max_spindle_rpm.value_or(1e5), qPrintable(where));
    QCOMPARE(window.document()->point().depth_mm, r.depth_mm);
    QVERIFY(!window.document()->isDirty());
  }
};

MX_REGISTER_TEST(TestLobesFeature)
#include "test_lobes_feature.moc"
