// The lobe chart and the operating point (offscreen main window): open, drag the operating point on
// the chart (the readouts show the engine's values), one undo step per drag, inch display, the tools
// shown on the chart, and a responsive event loop while the engine thread computes.
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTimer>
#include <QUndoStack>
#include <cmath>

#include "main_window.h"
#include "model/cutting_force.h"
#include "stability/stability_boundary.h"
#include "stability/zero_order_lobes.h"
#include "support/event_loop_probe.h"
#include "support/window_features.h"
#include "test_registry.h"

using namespace mx;

namespace {
const QString kRubio = QStringLiteral(MX_PROJECTS_DIR "/rubio2006-tool-selection.mxproj");

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
}  // namespace

class TestLobesFeature : public QObject {
  Q_OBJECT
 private slots:
  void opensProjectAndPlotsLobes() {
    gui::MainWindow window;
    window.setQuiet(true);
    QSignalSpy shown(test::lobesOf(window), &gui::LobesFeature::lobesShown);
    QVERIFY(window.openProject(kRubio));
    QVERIFY(shown.wait(20000));
    QCOMPARE(window.project()->tools.size(), size_t{2});
    QVERIFY(window.windowTitle().contains("rubio2006"));
    // View > Tools on the chart hides and shows a tool's lobes.
    test::lobesOf(window)->chart()->setToolVisible("R2", false);
    QVERIFY(!test::lobesOf(window)->chart()->isToolVisible("R2"));
    test::lobesOf(window)->chart()->setToolVisible("R2", true);
    QVERIFY(test::lobesOf(window)->chart()->isToolVisible("R2"));
  }

  // A press / move / release drag on the chart moves the point; the readouts equal an independent
  // engine evaluation (ZOA lobes of the project's tool, StabilityBoundary, evaluateCut).
  void dragMovesPointAndReadoutsMatchEngine() {
    gui::MainWindow window;
    QVERIFY(openAndShow(window, kRubio));
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
    QVERIFY(openAndShow(window, kRubio));
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
    QVERIFY(openAndShow(window, kRubio));
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
    QVERIFY(openAndShow(window, kRubio));
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
    QVERIFY(openAndShow(window, kRubio));
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
    QVERIFY(window.openProject(kRubio));
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
};

MX_REGISTER_TEST(TestLobesFeature)
#include "test_lobes_feature.moc"
