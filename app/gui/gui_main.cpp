// millexpert: the GUI. "millexpert [PROJECT]" opens PROJECT, else the bundled default project.
// "--screenshot FILE" saves the window once the lobes are shown, then quits (docs, CI).
#include <QApplication>
#include <QCommandLineParser>
#include <QFile>
#include <QTimer>
#include <clocale>

#include "main_window.h"

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  Q_INIT_RESOURCE(resources);  // the .qrc lives in the static millexpert_gui_core
  std::setlocale(LC_NUMERIC, "C");
  QApplication::setApplicationName("MillExpert");
  QApplication::setOrganizationName("MillExpert");
  QCommandLineParser parser;
  parser.setApplicationDescription("MillExpert: milling stability lobes, expert tool selection and control.");
  parser.addHelpOption();
  parser.addPositionalArgument("project", "Project file (.mxproj); default: the bundled example.");
  parser.addOption({"screenshot", "Save a screenshot of the window to FILE once the lobes and the first simulation are shown, then quit.",
                    "FILE"});
  parser.process(app);

  QString path = parser.positionalArguments().value(0);
  if (path.isEmpty()) path = QFile::exists(MX_DEFAULT_PROJECT) ? QString(MX_DEFAULT_PROJECT)
                                                               : QString("/usr/share/millexpert/projects/rubio2006-tool-selection.mxproj");
  mx::gui::MainWindow window;
  const QString screenshot = parser.value("screenshot");
  window.setQuiet(!screenshot.isEmpty());
  if (!screenshot.isEmpty()) window.resize(1920, 1080);  // docs screenshots at 1080p
  window.show();
  if (!screenshot.isEmpty()) {
    QObject::connect(&window, &mx::gui::MainWindow::simulationFinished, &window, [&window, screenshot] {
      QTimer::singleShot(300, &window, [&window, screenshot] {
        window.grab().save(screenshot);
        QApplication::quit();
      });
    });
    QTimer::singleShot(60000, &app, [] { QApplication::exit(1); });
  }
  if (!window.openProject(path) && !screenshot.isEmpty()) return 2;
  return app.exec();
}
