// millexpert: the GUI. "millexpert [PROJECT]" opens PROJECT, else the bundled default project (the start
// page when the examples are not found).
// "--point RPM,MM[,MM_PER_TOOTH]" picks the initial operating point; "--screenshot FILE" saves the
// window once the lobes and the point's simulation are shown, then quits (docs, scripts).
#include <QApplication>
#include <QComboBox>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QTextStream>
#include <QTimer>
#include <clocale>
#include <memory>

#include "example_projects.h"
#include "lobes_feature.h"
#include "machining_feature.h"
#include "main_window.h"
#include "mx_version.h"
#include "pareto_feature.h"
#include "simulation_feature.h"
#include "supervisor_feature.h"
#include "supervisor_view.h"
#include "tap_test_feature.h"
#include "tap_test_panel.h"

namespace {

// --help and --version print and quit: they need no display (a terminal over ssh, help2man at build time).
bool onlyPrints(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    for (const char* flag : {"--help", "-h", "-?", "--help-all", "--version", "-v"})
      if (qstrcmp(argv[i], flag) == 0) return true;
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (onlyPrints(argc, argv) && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  Q_INIT_RESOURCE(resources);  // the .qrc lives in the static millexpert_gui_core
  std::setlocale(LC_NUMERIC, "C");
  QApplication::setApplicationName("MillExpert");
  QApplication::setOrganizationName("MillExpert");
  QApplication::setApplicationVersion(mx::app::kVersion);
  QCommandLineParser parser;
  parser.setApplicationDescription("MillExpert: milling stability lobes, expert tool selection and control.");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument("project", "Project file (.mxproj); default: the bundled example.");
  parser.addOption({"point", "Initial operating point: speed [rpm], depth [mm] and optionally feed [mm/tooth].",
                    "RPM,MM[,MM_PER_TOOTH]"});
  parser.addOption({"screenshot",
                    "Save a screenshot of the window to FILE once the lobes and the point's "
                    "simulation are shown, then quit.",
                    "FILE"});
  parser.addOption({"docks", "Raise these docks (object names, e.g. paretoFrontDock,paretoWeightsDock).", "NAMES"});
  parser.addOption({"supervise",
                    "Run the supervisor with this controller (none, smc1, smc2) as fast as possible; "
                    "with --screenshot, the shot waits for its end.",
                    "CONTROLLER"});
  parser.addOption({"sdnrp", "Run the surface-finish (SDNRP) loop of the project once it is open."});
  parser.addOption({"program", "Open this G-code part program in the part-program panel.", "FILE"});
  parser.addOption({"method", "Lobe method: zoa (default) or sdm.", "METHOD"});
  parser.addOption({"fit-tap-test",
                    "Once the active tool's tap test for this direction (x or y) is shown, fit it; with "
                    "--screenshot, the shot waits for the fit.",
                    "DIRECTION"});
  parser.addOption({"pareto",
                    "Once the Pareto study is ready, move the operating point to the Pareto choice "
                    "and simulate it."});
  parser.process(app);

  // The bundled default, where the examples are (example_projects.h); none found: the start page.
  const QString path =
      parser.positionalArguments().value(0, mx::gui::exampleProject("rubio2006-tool-selection.mxproj"));
  mx::gui::MainWindow window;
  const QString screenshot = parser.value("screenshot");
  window.setQuiet(!screenshot.isEmpty());
  if (!screenshot.isEmpty()) window.resize(1920, 1080);  // docs screenshots at 1080p
  window.show();
  auto* lobes = window.findChild<mx::gui::LobesFeature*>("lobesFeature");
  auto* simulation = window.findChild<mx::gui::SimulationFeature*>("simulationFeature");
  auto* pareto_feature = window.findChild<mx::gui::ParetoFeature*>("paretoFeature");
  auto* supervisor = window.findChild<mx::gui::SupervisorFeature*>("supervisorFeature");
  auto* machining = window.findChild<mx::gui::MachiningFeature*>("machiningFeature");
  auto* tap_test = window.findChild<mx::gui::TapTestFeature*>("tapTestFeature");
  const QString fit_direction = parser.value("fit-tap-test");
  if (!fit_direction.isEmpty() && fit_direction != "x" && fit_direction != "y") {
    QTextStream(stderr) << "millexpert: --fit-tap-test = '" << fit_direction << "': must be x or y\n";
    return 2;
  }
  if (parser.isSet("method")) {
    const QString method = parser.value("method");
    if (method != "zoa" && method != "sdm") {
      QTextStream(stderr) << "millexpert: --method = '" << method << "': must be zoa or sdm\n";
      return 2;
    }
    lobes->setMethod(method == "zoa" ? mx::gui::LobeMethod::ZeroOrder : mx::gui::LobeMethod::SemiDiscretization);
  }
  if (!fit_direction.isEmpty()) {
    QObject::connect(tap_test, &mx::gui::TapTestFeature::measurementShown, &window,
                     [tap_test, fit_direction](const QString& direction) {
                       if (direction != fit_direction) return;
                       tap_test->panel()->setCurrentDirection(direction);
                       tap_test->panel()->requestFit();
                     });
  }
  if (parser.isSet("point")) {
    const QStringList parts = parser.value("point").split(',');
    bool ok_n = false, ok_b = false, ok_f = true;
    const double n = parts.value(0).toDouble(&ok_n), b = parts.value(1).toDouble(&ok_b);
    const double f = parts.size() > 2 ? parts[2].toDouble(&ok_f) : 0.0;
    if (!ok_n || !ok_b || !ok_f || n <= 0 || b < 0 || f < 0 || parts.size() > 3) {
      QTextStream(stderr) << "millexpert: --point = '" << parser.value("point")
                          << "': expected RPM,MM[,MM_PER_TOOTH] with RPM > 0, MM >= 0\n";
      return 2;
    }
    QObject::connect(
        lobes, &mx::gui::LobesFeature::lobesShown, &window,
        [&window, simulation, n, b, f] {
          mx::app::PickedPoint p = window.document()->point();
          p.speed_rpm = n;
          p.depth_mm = b;
          if (f > 0.0) p.feed_mm_per_tooth = f;
          window.document()->initPoint(p);
          simulation->start();
        },
        Qt::SingleShotConnection);
  }
  for (const QString& name : parser.value("docks").split(',', Qt::SkipEmptyParts))
    if (auto* dock = window.findChild<QDockWidget*>(name)) {
      dock->raise();
      // A raised bottom dock gets 40 % of the height (its plots need it, the chart keeps the most); a
      // right dock keeps its width.
      if (window.dockWidgetArea(dock) == Qt::BottomDockWidgetArea)
        window.resizeDocks({dock}, {window.height() * 40 / 100}, Qt::Vertical);
    }
  const bool pareto = parser.isSet("pareto");
  bool moved_to_pareto = false;
  if (pareto) {
    // Needs both the study (paretoShown) and the lobes of the tool (lobesShown), in either order.
    auto move = [&window, &moved_to_pareto, pareto_feature, simulation] {
      if (moved_to_pareto || !pareto_feature->choice() || window.document()->point().speed_rpm <= 0.0) return;
      moved_to_pareto = true;
      QTimer::singleShot(0, &window, [pareto_feature, simulation] {
        pareto_feature->moveToChoice();
        simulation->start();
      });
    };
    QObject::connect(pareto_feature, &mx::gui::ParetoFeature::paretoShown, &window, move);
    QObject::connect(lobes, &mx::gui::LobesFeature::lobesShown, &window, move);
  }
  if (!screenshot.isEmpty()) {
    const bool supervise = parser.isSet("supervise");
    auto shoot = [&window, screenshot] {
      QTimer::singleShot(300, &window, [&window, screenshot] {
        window.grab().save(screenshot);
        QApplication::quit();
      });
    };
    if (supervise) QObject::connect(supervisor, &mx::gui::SupervisorFeature::supervisionFinished, &window, shoot);
    if (!fit_direction.isEmpty()) {
      // Both the fit and the lobes (SDM takes longer than the fit), in either order.
      auto shown = std::make_shared<int>(0);
      auto both = [shown, shoot] {
        if (++*shown == 2) shoot();
      };
      QObject::connect(tap_test, &mx::gui::TapTestFeature::fitShown, &window, both, Qt::SingleShotConnection);
      QObject::connect(lobes, &mx::gui::LobesFeature::lobesShown, &window, both, Qt::SingleShotConnection);
    }
    QObject::connect(simulation, &mx::gui::SimulationFeature::simulationShown, &window, [&, screenshot] {
      if (supervise || !fit_direction.isEmpty()) return;  // the supervised run or the fit decides
      if (pareto && !moved_to_pareto) return;             // wait for the simulation of the Pareto choice
      QTimer::singleShot(300, &window, [&window, screenshot] {
        window.grab().save(screenshot);
        QApplication::quit();
      });
    });
    QTimer::singleShot(60000, &app, [] { QApplication::exit(1); });
  }
  if (!path.isEmpty() && !window.openProject(path) && !screenshot.isEmpty()) return 2;
  if (parser.isSet("sdnrp")) machining->runSurfaceFinish();
  if (parser.isSet("supervise")) {
    mx::widgets::SupervisorView* view = supervisor->view();
    view->setController(parser.value("supervise"));
    emit view->controllerChanged(parser.value("supervise"));
    view->speedCombo()->setCurrentIndex(view->speedCombo()->count() - 1);
    supervisor->start();
  }
  if (parser.isSet("program")) machining->openPartProgram(parser.value("program"));
  return app.exec();
}
