// Main window (offscreen): open, drag the operating point on the lobe chart (readouts show the
// engine's values), save/reopen, autosave recovery after a simulated crash, undo of a point move,
// and a responsive event loop while the engine thread computes.
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <cmath>

#include "document/project_validation.h"
#include "main_window.h"
#include "model/cutting_force.h"
#include "stability/stability_boundary.h"
#include "stability/zero_order_lobes.h"
#include "test_registry.h"

using namespace mx;

namespace {
const QString kRubio = QStringLiteral(MX_PROJECTS_DIR "/rubio2006-tool-selection.mxproj");

QString copyToTemp(const QTemporaryDir& dir, const QString& source) {
  const QString target = dir.filePath("project.mxproj");
  QFile::remove(target);
  QFile::copy(source, target);
  QFile(target).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
  return target;
}

// Shows the window (offscreen), opens `path` and waits for its lobes.
bool openAndShow(gui::MainWindow& window, const QString& path) {
  window.setQuiet(true);
  window.resize(1400, 900);
  window.show();
  QSignalSpy shown(&window, &gui::MainWindow::lobesShown);
  return window.openProject(path) && shown.wait(20000);
}

double readoutNumber(const gui::MainWindow& w, const QString& field) {
  return w.readout()->text(field).section(' ', 0, 0).toDouble();
}
}  // namespace

class TestMainWindow : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    QCoreApplication::setOrganizationName("MillExpertTest");
    QCoreApplication::setApplicationName("millexpert-test");
  }

  void opensProjectAndPlotsLobes() {
    gui::MainWindow window;
    window.setQuiet(true);
    QSignalSpy shown(&window, &gui::MainWindow::lobesShown);
    QVERIFY(window.openProject(kRubio));
    QVERIFY(shown.wait(20000));
    QCOMPARE(window.project()->tools.size(), size_t{2});
    QVERIFY(window.windowTitle().contains("rubio2006"));
    // View > Tools on the chart hides and shows a tool's lobes.
    window.lobeChart()->setToolVisible("R2", false);
    QVERIFY(!window.lobeChart()->isToolVisible("R2"));
    window.lobeChart()->setToolVisible("R2", true);
    QVERIFY(window.lobeChart()->isToolVisible("R2"));
  }

  // A press / move / release drag on the chart moves the point; the readouts equal an independent
  // engine evaluation (ZOA lobes of the project's tool, StabilityBoundary, evaluateCut).
  void dragMovesPointAndReadoutsMatchEngine() {
    gui::MainWindow window;
    QVERIFY(openAndShow(window, kRubio));
    widgets::LobeChartView* chart = window.lobeChart();
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
    QCOMPARE_LE(std::abs(readoutNumber(window, "mrr") - perf.mrr_m3_per_s * 1e9), 0.05);
    QCOMPARE(window.readout()->text("verdict").startsWith("STABLE"),
             boundary.isStable(n, b) && perf.peak_power_w <= 745.3);

    // The whole drag is one undo step.
    window.document()->undoStack()->undo();
    QVERIFY(std::abs(window.document()->point().speed_rpm - 4200.0) > 30.0);
  }

  // Inch display: the chart and readouts convert; the document stays in mm.
  void inchUnitsOnChartAndReadouts() {
    gui::MainWindow window;
    QVERIFY(openAndShow(window, kRubio));
    window.units()->setLength(widgets::DisplayUnits::Length::Inch);
    QWidget* plot = window.lobeChart()->plotWidget();
    const QPoint at = window.lobeChart()->pixelFor(4000.0, 0.5);
    QTest::mousePress(plot, Qt::LeftButton, Qt::NoModifier, at);
    QTest::mouseRelease(plot, Qt::LeftButton, Qt::NoModifier, at);
    QVERIFY(std::abs(window.document()->point().depth_mm - 0.5) < 0.01);
    QVERIFY(window.readout()->text("depth").endsWith(" in"));
    QCOMPARE_LE(std::abs(readoutNumber(window, "depth") - window.document()->point().depth_mm / 25.4), 1e-5);
  }

  void saveThenReopenIsIdentical() {
    QTemporaryDir dir;
    const QString path = copyToTemp(dir, kRubio);
    gui::MainWindow window;
    window.setQuiet(true);
    QVERIFY(window.openProject(path));
    app::Project edited = *window.project();
    edited.tools[0].modes_x[0].stiffness_N_per_um = 6.25;
    QCOMPARE(window.document()->applyEdit(edited, "stiffness"), QString());
    QVERIFY(window.document()->isDirty());
    const QString saved = dir.filePath("saved.mxproj");
    QVERIFY(window.saveProject(saved));
    QVERIFY(!window.document()->isDirty());
    const app::Project reopened = app::loadProject(saved);
    QCOMPARE(app::projectToJson(reopened), app::projectToJson(*window.project()));
    QCOMPARE(reopened.tools[0].modes_x[0].stiffness_N_per_um, 6.25);
  }

  void autosaveRecoveryAfterCrash() {
    QTemporaryDir dir;
    const QString path = copyToTemp(dir, kRubio);
    {
      gui::MainWindow window;
      window.setQuiet(true);
      QVERIFY(window.openProject(path));
      app::Project edited = *window.project();
      edited.machine->spindle_power_W = 999.0;
      QCOMPARE(window.document()->applyEdit(edited, "power"), QString());
      window.document()->writeAutosave();
      QVERIFY(QFile::exists(path + ".autosave"));
      // Simulated crash: the window goes away without closing (no save, autosave left behind).
    }
    QCOMPARE(app::ProjectDocument::recoveryCandidate(path), path + ".autosave");
    gui::MainWindow window;
    window.setQuiet(true);
    window.setRecoveryPolicy(gui::MainWindow::RecoveryPolicy::Recover);
    QVERIFY(window.openProject(path));
    QCOMPARE(window.project()->machine->spindle_power_W, 999.0);
    QVERIFY(window.document()->isDirty());   // recovered, not yet saved
    window.document()->undoStack()->undo();  // back to the file's content
    QCOMPARE(window.project()->machine->spindle_power_W, 745.3);
  }

  void untitledAutosaveGoesToTheDataFolder() {  // below the runner's private HOME, never a fixed path
    app::ProjectDocument document;
    document.newProject();
    app::Project edited = document.project();
    edited.name = "untitled edit";
    QCOMPARE(document.applyEdit(edited, "name"), QString());
    document.writeAutosave();
    const QString autosave = document.autosavePath();
    QVERIFY2(QFile::exists(autosave), qPrintable(autosave));
    QVERIFY2(autosave.startsWith(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/"),
             qPrintable(autosave));
    QVERIFY2(autosave.startsWith(QDir::homePath() + "/"), qPrintable(autosave));
    QVERIFY(QFile::remove(autosave));
  }

  void badProjectIsRefusedAndKeepsTheCurrentOne() {
    gui::MainWindow window;
    window.setQuiet(true);
    QVERIFY(window.openProject(MX_PROJECTS_DIR "/benchmark-insperger-1dof.mxproj"));
    QTemporaryDir dir;
    const QString bad = dir.filePath("bad.mxproj");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{ \"format\": \"millexpert-project\", \"version\": 1 ");
    f.close();
    QVERIFY(!window.openProject(bad));
    QCOMPARE(window.project()->tools.front().id, QString("FULL"));
  }

  // While the engine thread computes semi-discretization lobes of 200 speeds, the GUI event loop
  // keeps ticking (the largest gap is a benchmark figure, docs/performance.md; not gated here).
  void eventLoopKeepsTickingDuringSdm() {
    gui::MainWindow window;
    window.setQuiet(true);
    QSignalSpy shown(&window, &gui::MainWindow::lobesShown);
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
    QSignalSpy busy(window.engine(), &gui::EngineRunner::busyChanged);
    clock.start();
    timer.start();
    window.setMethod(gui::LobeMethod::SemiDiscretization);
    // Watch the loop until the job ends, or for 3 s (sanitizer builds are far slower).
    const bool finished = shown.wait(3000) || shown.count() > 0;
    const qint64 elapsed = clock.elapsed();
    timer.stop();
    qInfo("SDM lobes (2 tools, 2 x 200 speeds): %s after %lld ms; %d ticks; largest gap %lld ms",
          finished ? "finished" : "still running", elapsed, ticks, largest_gap);
    QVERIFY(busy.count() >= 1);
    window.engine()->cancelAll();
    QVERIFY(ticks >= 5);
  }
};

MX_REGISTER_TEST(TestMainWindow)
#include "test_main_window.moc"
