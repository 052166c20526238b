// Scenario "screenshots": the pictures of the README and docs/, each from a fresh window at 1920x1080
// on the X screen with a bundled project, once what the picture is about has arrived (the lobes, the
// point's simulation, a Pareto choice, a supervised run, a tap-test fit...). A shot that never gets
// there fails, naming what it waited for; packaging/screenshots.sh runs this scenario.
#include "e2e_screenshots.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QGuiApplication>
#include <QImage>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <algorithm>
#include <functional>
#include <memory>
#include <optional>

#include "e2e_batch.h"
#include "e2e_driver.h"
#include "e2e_learning.h"
#include "e2e_report.h"
#include "e2e_screen_scan.h"
#include "e2e_window.h"
#include "guide_window.h"
#include "help_feature.h"
#include "machine_operation_panel.h"
#include "machining_feature.h"
#include "material_choices.h"
#include "pareto_feature.h"
#include "shop_units_dialog.h"
#include "supervisor_feature.h"
#include "supervisor_view.h"
#include "support/window_features.h"
#include "tap_test_feature.h"
#include "tap_test_panel.h"
#include "tool_import_dialog.h"
#include "tool_library_editor.h"
#include "tool_library_transfer.h"

namespace mx::e2e {

namespace {

constexpr int kShotMs = 180000;  // the slowest shot (a supervised run, SDM lobes) with margin

struct Point {
  double speed_rpm, depth_mm, feed_mm_per_tooth;
};

struct Shot {
  const char* file;
  const char* project;              // in projects/
  std::optional<Point> point = {};  // the operating point, else the window's initial one
  const char* docks = "";           // raised, comma separated object names
  bool pareto = false;              // move to the Pareto choice and simulate it
  const char* supervise = "";       // run the supervisor with this controller
  bool compare = false;             // compare the three supervisory controllers
  bool sdnrp = false;               // run the surface-finish loop
  const char* program = "";         // open this part program (in projects/)
  bool sdm = false;                 // semi-discretization lobes
  const char* fit = "";             // fit the tap test of this direction
  bool inch = false;                // the Inch shop units (in, SFM, IPM, in/tooth, hp, lbf, in³/min)
  bool preferences = false;         // Edit > Preferences... open over the window (a grab of the screen)
  const char* library = "";         // imported (in projects/), then its import dialog open over the window
  const char* material = "";        // copied from the materials library through the material panel's picker
  bool start_page = false;          // a window without a project: the start page, `project` a recent one
  bool guide = false;               // Help > User guide open beside the window (a grab of the screen)
  bool learning = false;            // the learning database seeded, its history shown
  bool learning_settings = false;   // Settings > Learning database open, its connection tested
  bool batch = false;               // File > Batch study run here, its merged table shown
};

const Shot kShots[] = {
    {.file = "main-window.png", .project = "rubio2006-tool-selection.mxproj"},
    {.file = "chatter.png", .project = "rubio2006-tool-selection.mxproj", .point = Point{5100, 1.2, 0.1}},
    {.file = "insperger-benchmark.png", .project = "benchmark-insperger-1dof.mxproj"},
    {.file = "pareto-front.png",
     .project = "rubio-pareto-case.mxproj",
     .docks = "paretoFrontDock,paretoWeightsDock",
     .pareto = true},
    {.file = "pareto-choice.png", .project = "rubio-pareto-case.mxproj", .docks = "paretoWeightsDock", .pareto = true},
    {.file = "pareto-monitoring.png",
     .project = "rubio-pareto-case.mxproj",
     .docks = "monitoringDock,operatorRulesDock",
     .pareto = true},
    {.file = "force-control.png", .project = "rubio2006-adaptive-control.mxproj", .docks = "controlDock"},
    {.file = "force-control-programme.png", .project = "rubio-pareto-case.mxproj", .docks = "controlDock"},
    {.file = "surface-finish.png", .project = "cus-zuperl-sdnrp.mxproj", .docks = "surfaceFinishDock", .sdnrp = true},
    {.file = "part-program.png",
     .project = "cus-zuperl-sdnrp.mxproj",
     .docks = "partProgramDock",
     .program = "programs/pocket_mm.nc"},
    {.file = "part-program-heidenhain.png",
     .project = "cus-zuperl-sdnrp.mxproj",
     .docks = "partProgramDock",
     .program = "programs/pocket_mm.h"},
    {.file = "supervisor.png",
     .project = "landers-face-milling.mxproj",
     .docks = "supervisorDock",
     .supervise = "smc2"},
    {.file = "supervisor-compare.png",
     .project = "landers-face-milling.mxproj",
     .docks = "supervisorDock",
     .compare = true},
    {.file = "tap-test.png", .project = "tap-test-example.mxproj", .fit = "x"},
    {.file = "tap-test-lobes-sdm.png", .project = "tap-test-example.mxproj", .sdm = true, .fit = "y"},
    {.file = "shop-units-inch.png", .project = "rubio2006-tool-selection.mxproj", .inch = true},
    {.file = "shop-units-settings.png",
     .project = "rubio2006-tool-selection.mxproj",
     .inch = true,
     .preferences = true},
    {.file = "tool-import.png",
     .project = "rubio2006-tool-selection.mxproj",
     .docks = "toolsDock",
     .library = "libraries/fusion-endmills.json"},
    {.file = "material-library.png",
     .project = "rubio2006-tool-selection.mxproj",
     .docks = "machineDock",
     .material = "Al7075-T6"},
    {.file = "start-screen.png", .project = "rubio-pareto-case.mxproj", .start_page = true},
    {.file = "user-guide.png", .project = "rubio2006-tool-selection.mxproj", .guide = true},
    {.file = "learning-history.png", .project = "rubio-pareto-case.mxproj", .docks = "historyDock", .learning = true},
    {.file = "learning-database-settings.png",
     .project = "rubio-pareto-case.mxproj",
     .docks = "historyDock",
     .learning = true,
     .learning_settings = true},
    {.file = "batch-study.png", .project = "rubio2006-tool-selection.mxproj", .batch = true},
};

QString projectFile(const char* relative) {
  return QStringLiteral(MX_PROJECTS_DIR "/") + relative;
}

// The docks raised as gui_main's --docks does: a bottom dock gets 40 % of the height for its plots.
void raiseDocks(gui::MainWindow& window, const QString& names) {
  for (const QString& name : names.split(',', Qt::SkipEmptyParts)) {
    auto* dock = part<QDockWidget>(window, name);
    dock->raise();
    if (window.dockWidgetArea(dock) == Qt::BottomDockWidgetArea)
      window.resizeDocks({dock}, {window.height() * 40 / 100}, Qt::Vertical);
  }
}

// Copies the library entry `id` into the project through the panel's picker, as a click would, waits
// until the lobes and the simulation of the new material are shown, and scrolls the material group into
// view.
void pickMaterial(gui::MainWindow& window, const QString& id) {
  auto* panel = part<widgets::MachineOperationPanel>(window);
  auto* picker = qobject_cast<QComboBox*>(panel->field("material.library"));
  const QList<widgets::MaterialChoice> choices = gui::bundledMaterialChoices();
  const auto entry = std::find_if(choices.begin(), choices.end(),
                                  [&id](const widgets::MaterialChoice& c) { return c.material.library == id; });
  if (entry == choices.end()) throw Aborted(QString("the materials library has no entry %1").arg(id));
  QSignalSpy lobes_shown(test::lobesOf(window), &gui::LobesFeature::lobesShown);
  QSignalSpy simulated(test::simulationOf(window), &gui::SimulationFeature::simulationShown);
  emit picker->activated(int(entry - choices.begin()));
  waitFor([&] { return lobes_shown.count() > 0 && simulated.count() > 0; }, kShotMs,
          "the lobes and the simulation of the library's material");
  QTest::qWait(100);  // the panel's layout after the edit
  auto* area = qobject_cast<QScrollArea*>(panel->parentWidget()->parentWidget());
  if (!area) throw Aborted("the material panel is not in its dock's scroll area");
  area->ensureWidgetVisible(panel->field("material.process_damping_N_per_m"), 0, 20);
}

// The start page of a window opened without a project, after `recent` and two other examples were
// opened (the e2e run's own settings, as a user's File > Open recent keeps them).
std::unique_ptr<gui::MainWindow> startPage(const QString& recent) {
  QSettings().setValue("recentFiles", QStringList{projectFile("tap-test-example.mxproj"), recent,
                                                  projectFile("rubio2006-tool-selection.mxproj")});
  std::unique_ptr<gui::MainWindow> window = showWindow();
  auto* help = part<gui::HelpFeature>(*window, "helpFeature");
  waitFor([help] { return help->startScreenShown(); }, kShotMs, "the start page of a window without a project");
  QTest::qWait(500);  // its first paint
  return window;
}

// Help > User guide, placed over the right of the window (Xvfb has no window manager to do it).
QWidget* openGuide(gui::MainWindow& window) {
  QAction* guide = part<QAction>(window, "userGuideAction");
  guide->trigger();
  auto* shown = part<widgets::GuideWindow>(window, "guideWindow");
  shown->setGeometry(560, 0, 1360, 1080);
  return shown;
}

// Imports every tool of `library` into the window's project, selects the first one imported, and
// opens the import dialog on the same library (as Import library... shows it).
QDialog* importDialog(Report& report, gui::MainWindow& window, const QString& library) {
  gui::ToolLibraryTransfer* transfer = test::editorsOf(window)->libraryTransfer();
  QSignalSpy finished(transfer, &gui::ToolLibraryTransfer::importFinished);
  app::ImportedLibrary read;
  transfer->importFile(library, std::nullopt, {}, [&read](const QString&, const app::ImportedLibrary& l) {
    read = l;
    return std::optional<gui::ToolLibraryTransfer::Choice>(gui::ToolLibraryTransfer::Choice{});
  });
  waitFor([&finished] { return finished.count() > 0; }, kShotMs, "the tool-library import");
  report.check("tool-import.imported", finished.at(0).at(0).toString().isEmpty(), finished.at(0).at(0).toString());
  if (!read.tools.empty()) test::editorsOf(window)->toolEditor()->selectTool(read.tools.front().id);
  QStringList skipped;
  for (const app::SkippedTool& t : read.skipped) skipped << QString("%1: %2").arg(t.name, t.reason);
  auto* dialog = new widgets::ToolImportDialog(QFileInfo(library).fileName(), read.tools, skipped,
                                               int(window.project()->tools.size()), window.units(), &window);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->show();
  return dialog;
}

void saveShot(Report& report, const Shot& shot, const QDir& folder, const QImage& image, const QWidget& window) {
  const QString path = folder.filePath(shot.file);
  report.check(QString("%1.saved").arg(shot.file), image.save(path), path);
  report.check(QString("%1.size").arg(shot.file), image.size() == QSize(1920, 1080),
               QString("%1x%2; the window's minimum size is %3x%4")
                   .arg(image.width())
                   .arg(image.height())
                   .arg(window.minimumSizeHint().width())
                   .arg(window.minimumSizeHint().height()));
}

void takeShot(Report& report, const Shot& shot, const QDir& folder) {
  if (shot.start_page) {
    std::unique_ptr<gui::MainWindow> window = startPage(projectFile(shot.project));
    return saveShot(report, shot, folder, window->grab().toImage(), *window);
  }
  if (shot.learning) seedLearningDatabase(report);
  std::unique_ptr<gui::MainWindow> owner = showWindow();
  gui::MainWindow& window = *owner;
  // Each shot in its own units, whatever an earlier run left in the settings.
  window.units()->setShop(shot.inch ? widgets::ShopUnits::inch() : widgets::ShopUnits::metric());
  gui::LobesFeature* lobes = test::lobesOf(window);
  gui::SimulationFeature* simulation = test::simulationOf(window);
  gui::ParetoFeature* pareto = test::paretoOf(window);
  auto* supervisor = part<gui::SupervisorFeature>(window, "supervisorFeature");
  auto* machining = part<gui::MachiningFeature>(window, "machiningFeature");
  auto* tap_test = part<gui::TapTestFeature>(window, "tapTestFeature");
  const QString fit = shot.fit;

  QSignalSpy lobes_shown(lobes, &gui::LobesFeature::lobesShown);
  QSignalSpy simulated(simulation, &gui::SimulationFeature::simulationShown);
  QSignalSpy supervised(supervisor, &gui::SupervisorFeature::supervisionFinished);
  QSignalSpy compared(supervisor, &gui::SupervisorFeature::comparisonResult);
  QSignalSpy surface(machining, &gui::MachiningFeature::surfaceFinishShown);
  QSignalSpy program(machining, &gui::MachiningFeature::partProgramShown);
  QSignalSpy fitted(tap_test, &gui::TapTestFeature::fitShown);
  // The simulation that counts is the one of the shot's final point: the count when it was started.
  qsizetype final_simulation = shot.point || shot.pareto ? -1 : 0;

  if (shot.sdm) lobes->setMethod(gui::LobeMethod::SemiDiscretization);
  if (!fit.isEmpty())
    QObject::connect(tap_test, &gui::TapTestFeature::measurementShown, &window, [tap_test, fit](const QString& d) {
      if (d != fit) return;
      tap_test->panel()->setCurrentDirection(d);
      tap_test->panel()->requestFit();
    });
  if (shot.point)
    QObject::connect(
        lobes, &gui::LobesFeature::lobesShown, &window,
        [&window, simulation, &simulated, &final_simulation, p = *shot.point] {
          app::PickedPoint q = window.document()->point();
          q.speed_rpm = p.speed_rpm;
          q.depth_mm = p.depth_mm;
          q.feed_mm_per_tooth = p.feed_mm_per_tooth;
          window.document()->initPoint(q);
          final_simulation = simulated.count();
          simulation->start();
        },
        Qt::SingleShotConnection);
  if (shot.pareto) {
    // Needs the study and the lobes, in either order; once.
    auto moved = std::make_shared<bool>(false);
    auto move = [&window, pareto, simulation, &simulated, &final_simulation, moved] {
      if (*moved || !pareto->choice() || window.document()->point().speed_rpm <= 0.0) return;
      *moved = true;
      QTimer::singleShot(0, &window, [pareto, simulation, &simulated, &final_simulation] {
        pareto->moveToChoice();
        final_simulation = simulated.count();
        simulation->start();
      });
    };
    QObject::connect(pareto, &gui::ParetoFeature::paretoShown, &window, move);
    QObject::connect(lobes, &gui::LobesFeature::lobesShown, &window, move);
  }
  raiseDocks(window, shot.docks);

  report.require(QString("%1.open").arg(shot.file), window.openProject(projectFile(shot.project)), shot.project);
  if (shot.sdnrp) machining->runSurfaceFinish();
  if (*shot.supervise) {
    widgets::SupervisorView* view = supervisor->view();
    view->setController(shot.supervise);
    emit view->controllerChanged(shot.supervise);
    view->speedCombo()->setCurrentIndex(view->speedCombo()->count() - 1);  // as fast as possible
    supervisor->start();
  }
  if (shot.compare) {
    supervisor->view()->tabs()->setCurrentIndex(1);
    supervisor->compare();
  }
  if (*shot.program) machining->openPartProgram(projectFile(shot.program));

  QStringList waits = {"lobes"};
  std::vector<std::function<bool()>> ready = {[&] { return lobes_shown.count() > 0; }};
  if (*shot.supervise) {
    waits << "the supervised run";
    ready.emplace_back([&] { return supervised.count() > 0; });
  } else if (shot.compare) {
    waits << "the three supervised runs";
    ready.emplace_back([&] { return compared.count() >= 3; });
  } else if (!fit.isEmpty()) {
    waits << "the tap-test fit";
    ready.emplace_back([&] {
      for (const QList<QVariant>& args : fitted)
        if (args.value(0).toString() == fit) return true;
      return false;
    });
  } else {
    waits << "the simulation of the point";
    ready.emplace_back([&] { return final_simulation >= 0 && simulated.count() > final_simulation; });
  }
  if (shot.sdnrp) {
    waits << "the surface-finish run";
    ready.emplace_back([&] { return surface.count() > 0; });
  }
  if (*shot.program) {
    waits << "the part-program override";
    ready.emplace_back([&] { return program.count() > 0; });
  }
  waitFor(
      [&ready] {
        for (const auto& r : ready)
          if (!r()) return false;
        return true;
      },
      kShotMs, QString("%1: %2").arg(shot.file, waits.join(", ")));
  if (shot.learning) waitForLearningHistory(window, kShotMs);
  QTest::qWait(300);  // the last repaints (queued replots) before the grab

  QDialog* dialog = shot.preferences ? window.openPreferences() : nullptr;
  if (shot.learning_settings) dialog = learningDatabaseDialog(window, kShotMs);
  const QTemporaryDir batch_folder;
  if (shot.batch) dialog = batchStudyDialog(window, batch_folder.path(), kShotMs);
  if (*shot.library) dialog = importDialog(report, window, projectFile(shot.library));
  if (dialog) {
    dialog->move(window.geometry().center() - dialog->rect().center());
    QTest::qWait(300);
  }
  if (*shot.material) {
    pickMaterial(window, shot.material);
    QTest::qWait(300);
  }
  QWidget* guide = shot.guide ? openGuide(window) : nullptr;
  if (guide) QTest::qWait(500);  // its first paint
  // A dialog or the guide is a window of its own: the screen holds both.
  const QImage image = dialog || guide
                           ? QGuiApplication::primaryScreen()->grabWindow(0).toImage().copy(0, 0, 1920, 1080)
                           : window.grab().toImage();
  const QStringList cut = cutWrappedLabels(window);
  report.check(QString("%1.no-cut-text").arg(shot.file), cut.isEmpty(), cut.join("; "));
  if (guide) guide->close();
  if (dialog) dialog->reject();
  saveShot(report, shot, folder, image, window);
}

}  // namespace

QStringList screenshotNames() {
  QStringList names;
  for (const Shot& s : kShots) names << s.file;
  return names;
}

void runScreenshots(Report& report, const QString& folder, const QStringList& only) {
  const QDir dir(folder);
  report.require("screenshots.folder", QDir().mkpath(folder), folder);
  for (const QString& name : only)
    report.require("screenshots.name", screenshotNames().contains(name), "'" + name + "' among the shots");
  for (const Shot& shot : kShots) {
    if (!only.isEmpty() && !only.contains(shot.file)) continue;
    try {
      takeShot(report, shot, dir);
    } catch (const Aborted& e) {
      report.abort(QString::fromStdString(e.what()));  // the other shots still run
    }
  }
}

}  // namespace mx::e2e
