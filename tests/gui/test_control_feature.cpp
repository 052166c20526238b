// The control and machining docks of the main window: the project's control section
// drives the closed loop on the engine thread and its result reaches the view (traces, metrics equal
// to an independent engine run, pole-zero map, J_c sweep); a beta change is one undoable edit of
// control.beta; an invalid workpiece is refused with the project unchanged; the surface-finish panel
// runs the SDNRP loop and, compared, the same cut without SDNRP (dashed, equal to an engine run with
// control off; constant feed; gone when not compared); a part program is overridden and exported (only F/S words and
// comments change); a tool-table edit re-runs the control view, which then agrees with the CLI on the saved project; a
// drag of the beta slider is one undo step.
#include <QApplication>
#include <QFile>
#include <QJsonArray>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>

#include "control/closed_loop.h"
#include "control_beta_slider.h"
#include "control_feature.h"
#include "control_metrics_panel.h"
#include "control_view.h"
#include "document/project.h"
#include "jc_curve_plot.h"
#include "machining_feature.h"
#include "main_window.h"
#include "monitoring_panel.h"
#include "part_program_panel.h"
#include "sdnrp/sdnrp_simulator.h"
#include "services/control_request.h"
#include "services/sdnrp_request.h"
#include "support/cli_runner.h"
#include "support/project_files.h"
#include "support/window_features.h"
#include "surface_finish_panel.h"
#include "test_registry.h"
#include "tool_library_editor.h"
#include "tool_table_model.h"

using namespace mx;

namespace {
bool open(gui::MainWindow& w, const char* project) {
  w.setQuiet(true);
  w.resize(1600, 950);
  w.show();
  return w.openProject(mx::test::exampleCopy(project));
}

gui::ControlFeature* control(const gui::MainWindow& w) {
  return w.findChild<gui::ControlFeature*>("controlFeature");
}
gui::MachiningFeature* machining(const gui::MainWindow& w) {
  return w.findChild<gui::MachiningFeature*>("machiningFeature");
}
}  // namespace

class TestControlFeature : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-test");
  }

  void closedLoopReachesTheView() {
    gui::MainWindow window;
    QSignalSpy shown(control(window), &gui::ControlFeature::controlShown);
    QSignalSpy swept(control(window), &gui::ControlFeature::controlSweepShown);
    QVERIFY(open(window, "rubio2006-adaptive-control.mxproj"));
    QVERIFY(shown.count() > 0 || shown.wait(30000));
    widgets::ControlView* view = control(window)->view();
    QVERIFY(view->isEnabled());
    QCOMPARE(view->beta(), -0.3);
    // An independent engine run of the same project section gives the same samples.
    const app::ControlRequest request = app::controlRequestFromProject(*window.project());
    const ClosedLoopResult direct = simulateAdaptiveForceControl(request.settings);
    QCOMPARE(view->graphPointCount("force sampled"), static_cast<int>(direct.samples.size()));
    QCOMPARE(view->graphPointCount("force continuous"), static_cast<int>(direct.dense.size()));
    QVERIFY(view->graphPointCount("poles") >= 2);
    QVERIFY(swept.count() > 0 || swept.wait(60000));
    QCOMPARE(view->graphPointCount("Jc"), 41);  // -1:1:0.05

    // A beta change: one undoable edit of control.beta, and a new run.
    shown.clear();
    emit view->betaChanged(0.3);
    QCOMPARE(app::projectToJson(*window.project()).value("control").toObject().value("beta").toDouble(), 0.3);
    QVERIFY(shown.wait(30000));
    window.document()->undoStack()->undo();
    QCOMPARE(app::projectToJson(*window.project()).value("control").toObject().value("beta").toDouble(), -0.3);
    QCOMPARE(view->beta(), -0.3);

    // A workpiece with a negative depth is refused: the project is unchanged.
    const QJsonValue before = app::projectToJson(*window.project()).value("control");
    emit view->workpieceEdited({{5.0, 2.0}, {5.0, -1.0}});
    QCOMPARE(app::projectToJson(*window.project()).value("control"), before);
  }

  void toolTableEditReRunsTheControlView() {
    // C1's teeth 4 -> 2 in the tool table: the control view runs again and shows what the CLI
    // computes on the saved project, not the 4-tooth result.
    gui::MainWindow window;
    QSignalSpy shown(control(window), &gui::ControlFeature::controlShown);
    QVERIFY(open(window, "rubio2006-adaptive-control.mxproj"));
    QVERIFY(shown.count() > 0 || shown.wait(30000));
    widgets::ControlMetricsPanel* metrics = control(window)->view()->metricsPanel();
    const QString four_teeth_jc = metrics->valueText("jc");

    widgets::ToolTableModel* tools = test::editorsOf(window)->toolEditor()->toolModel();
    int row = 0;
    while (row < tools->rowCount() && tools->index(row, widgets::ToolTableModel::Id).data().toString() != "C1") ++row;
    QVERIFY(row < tools->rowCount());
    shown.clear();
    QVERIFY(tools->setData(tools->index(row, widgets::ToolTableModel::Teeth), 2, Qt::EditRole));
    QCOMPARE(window.project()->tools[static_cast<std::size_t>(row)].teeth, 2);
    QVERIFY(shown.wait(30000));

    QTemporaryDir dir;
    const QString saved = dir.filePath("two-teeth.mxproj");
    window.document()->save(saved);
    const mx::test::CliRun cli =
        mx::test::runCli({"control", saved, "--beta", QString::number(control(window)->view()->beta(), 'g', 17)});
    QCOMPARE(cli.code, 0);
    const QString cli_jc = widgets::MonitoringPanel::formatNumber(cli.json.value("Jc").toDouble());
    QCOMPARE(metrics->valueText("jc"), cli_jc);
    QVERIFY(cli_jc != four_teeth_jc);
    // The J_c plot's marker shows that same computed number, not the sweep's interpolation.
    widgets::JcCurvePlot* jc = control(window)->view()->jcPlot();
    QVERIFY(jc->computedJc());
    QCOMPARE_LE(std::abs(*jc->computedJc() - cli.json.value("Jc").toDouble()), 1e-9 * std::abs(*jc->computedJc()));
    QVERIFY2(jc->legendNames().last().contains(QString("J_c = %1 N").arg(*jc->computedJc(), 0, 'g', 4)),
             qPrintable(jc->legendNames().last()));
  }

  void betaSliderDragIsOneUndoStep() {
    gui::MainWindow window;
    QSignalSpy shown(control(window), &gui::ControlFeature::controlShown);
    QVERIFY(open(window, "rubio2006-adaptive-control.mxproj"));
    QVERIFY(shown.count() > 0 || shown.wait(30000));
    QUndoStack* undo = window.document()->undoStack();
    const int steps = undo->count();
    QSlider* slider = control(window)->view()->betaSlider();
    slider->setSliderDown(true);
    for (int ticks : {-20, 0, 20, 40}) {
      slider->setValue(ticks);
      // A pause longer than the debounce applies the value (waited for: a loaded machine is slower).
      QTest::qWait(widgets::ControlBetaSlider::kDebounceMs + 100);
      QTRY_COMPARE_WITH_TIMEOUT(*window.project()->control->beta, ticks / 100.0, 5000);
    }
    slider->setValue(50);
    slider->setSliderDown(false);
    QCOMPARE(*window.project()->control->beta, 0.5);
    QCOMPARE(undo->count(), steps + 1);
    undo->undo();
    QCOMPARE(*window.project()->control->beta, -0.3);  // the value before the drag
    QCOMPARE(control(window)->view()->beta(), -0.3);
  }

  void surfaceFinishRunsTheLoop() {
    gui::MainWindow window;
    QVERIFY(open(window, "cus-zuperl-sdnrp.mxproj"));
    widgets::SurfaceFinishPanel* panel = machining(window)->surfacePanel();
    QCOMPARE(panel->desiredRaUm(), 0.81);  // sdnrp.ra_um of the project
    QSignalSpy shown(machining(window), &gui::MachiningFeature::surfaceFinishShown);
    machining(window)->runSurfaceFinish();
    QVERIFY(shown.wait(30000));
    QCOMPARE(panel->sampleCount(), 1501);  // 15 s every 10 ms, t = 0 included
    QVERIFY(!panel->summaryText("f_final_n").isEmpty());
  }

  void surfaceFinishComparesWithoutSdnrp() {
    gui::MainWindow window;
    QVERIFY(open(window, "cus-zuperl-sdnrp.mxproj"));
    widgets::SurfaceFinishPanel* panel = machining(window)->surfacePanel();
    QVERIFY(panel->compareOn());
    QSignalSpy shown(machining(window), &gui::MachiningFeature::surfaceFinishShown);
    machining(window)->runSurfaceFinish();
    QVERIFY(shown.wait(30000));
    QCOMPARE(panel->sampleCount(), 1501);
    QCOMPARE(panel->baselineSampleCount(), 1501);
    for (const char* g : {"ra_baseline", "force_baseline", "feed_baseline", "speed_baseline"}) {
      QCOMPARE(panel->graphDataCount(g), 1501);
      QVERIFY2(panel->graphInLegend(g), g);
      QCOMPARE(panel->graphPenStyle(g), Qt::DashLine);
    }
    // The project's initial cutting conditions (Table 1: 430.41 mm/min, 1571 rpm) held all along.
    QCOMPARE(panel->graphValueRange("feed_baseline")->first, 430.41);
    QCOMPARE(panel->graphValueRange("feed_baseline")->second, 430.41);
    QCOMPARE(panel->graphValueRange("speed_baseline")->second, 1571.0);
    // The baseline is the engine's run without control, same settings and seed.
    SdnrpSettings s = app::sdnrpSettingsFromProject(*window.project());
    s.control = false;
    const SdnrpResult direct = SdnrpSimulator(s).run();
    QCOMPARE(panel->summaryText("ra_baseline_um"), widgets::MonitoringPanel::formatNumber(direct.ra_produced_m * 1e6));
    QCOMPARE(panel->summaryText("f_baseline_n"), widgets::MonitoringPanel::formatNumber(direct.f_final_N));
    double lo = direct.samples.front().force_dynamic_N, hi = lo;
    for (const SdnrpSample& x : direct.samples) {
      lo = std::min(lo, x.force_dynamic_N);
      hi = std::max(hi, x.force_dynamic_N);
    }
    QCOMPARE(panel->graphValueRange("force_baseline")->first, lo);
    QCOMPARE(panel->graphValueRange("force_baseline")->second, hi);
    // Without SDNRP F scatters about K4(1571, 430.41) = 225 N; with it F settles at F_d = 188 N.
    QVERIFY(panel->graphValueRange("force_baseline")->first > 210.0);
    QVERIFY(panel->graphValueRange("force_dynamic")->first < 190.0);

    panel->setCompareOn(false);
    shown.clear();
    machining(window)->runSurfaceFinish();
    QVERIFY(shown.wait(30000));
    QCOMPARE(panel->sampleCount(), 1501);
    QCOMPARE(panel->baselineSampleCount(), 0);
    QVERIFY(!panel->graphInLegend("force_baseline"));
  }

  void partProgramOverrideAndExport() {
    gui::MainWindow window;
    QVERIFY(open(window, "cus-zuperl-sdnrp.mxproj"));
    QSignalSpy shown(machining(window), &gui::MachiningFeature::partProgramShown);
    const QString program = MX_TEST_DATA_DIR "/gcode/pocket_mm.nc";
    machining(window)->openPartProgram(program);
    QVERIFY(shown.wait(30000));
    widgets::PartProgramPanel* panel = machining(window)->programPanel();
    QVERIFY(panel->changedCount() >= 1);
    QFile in(program);
    QVERIFY(in.open(QIODevice::ReadOnly));
    const QList<QByteArray> input = in.readAll().split('\n');
    QCOMPARE(panel->rows().size(), input.size() - (input.last().isEmpty() ? 1 : 0));
    // N50 gets a new F; N60 (no F of its own) runs at it: its new F is the modal one, from N50's line.
    const auto byBlock = [&](const char* n) {
      for (const widgets::PartProgramRow& r : panel->rows())
        if (r.text.startsWith(n)) return r;
      return widgets::PartProgramRow{};
    };
    const widgets::PartProgramRow n50 = byBlock("N50 "), n60 = byBlock("N60 ");
    QVERIFY(n50.new_feed.has_value() && n50.changed);
    QCOMPARE(n60.new_feed, n50.new_feed);
    QCOMPARE(n60.new_feed_from_line, n50.line);
    QCOMPARE(byBlock("N40 ").new_feed_from_line, 0);
    QTemporaryDir dir;
    QVERIFY(machining(window)->exportPartProgram(dir.filePath("out.nc")));
    QVERIFY(machining(window)->exportPartProgramCsv(dir.filePath("out.csv")));
    QFile out(dir.filePath("out.nc"));
    QVERIFY(out.open(QIODevice::ReadOnly));
    const QByteArray text = out.readAll();
    QVERIFY(text.contains("(MillExpert optimised part program)"));
    QVERIFY(text.contains("(project: cus-zuperl-sdnrp.mxproj)"));
    QCOMPARE(text.count('\n'), input.size() - 1 + 4);  // four header lines
  }
};

MX_REGISTER_TEST(TestControlFeature)
#include "test_control_feature.moc"
