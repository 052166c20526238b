// millexpert-e2e: drives the real MillExpert main window on a real X server (Xvfb) with real input
// events (xdotool), docs/testing.md.
//   millexpert-e2e check                      the end-to-end test (CTest e2e.window); exit 0 when every
//                                             check passes, 1 naming the failed checks
//   millexpert-e2e screenshots DIR [FILE...]  the README's and docs' pictures into DIR
//                                             (packaging/screenshots.sh)
//   millexpert-e2e monkey [--seed N] [--seconds S] [--project FILE]
//                                             random input on every dock (CTest e2e.monkey)
// A check that cannot run (no X display, not the xcb platform, a screen under 1920x1080, no xdotool)
// fails.
#include <QApplication>
#include <QElapsedTimer>
#include <QStringList>
#include <QTextStream>
#include <clocale>
#include <cstdio>

#include "e2e_check.h"
#include "e2e_driver.h"
#include "e2e_environment.h"
#include "e2e_monkey.h"
#include "e2e_monkey_supervisor.h"
#include "e2e_report.h"
#include "e2e_screenshots.h"

namespace {

int usage() {
  std::fprintf(stderr,
               "usage: millexpert-e2e check\n"
               "       millexpert-e2e screenshots DIR [FILE...]   (FILE: %s)\n"
               "       millexpert-e2e monkey [--seed N] [--seconds S] [--project FILE]\n",
               qPrintable(mx::e2e::screenshotNames().join(", ")));
  return 2;
}

int fail(const QString& message) {
  std::fprintf(stderr, "millexpert-e2e: FAIL: %s\n", qPrintable(message));
  return 1;
}

int finish(const mx::e2e::Report& report, qint64 elapsed_ms) {
  QTextStream out(stdout);
  out << QString("millexpert-e2e: %1 checks passed, %2 failed, %3 s")
             .arg(report.passed())
             .arg(report.failures())
             .arg(elapsed_ms / 1000.0, 0, 'f', 1)
      << Qt::endl;
  if (report.failures() == 0) return 0;
  out << "failed:" << Qt::endl;
  for (const QString& f : report.failed()) out << "  " << f << Qt::endl;
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  const QString scenario = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QString();
  if (scenario != "check" && scenario != "monkey" && !(scenario == "screenshots" && argc > 2)) return usage();
  mx::e2e::MonkeyOptions monkey;
  if (scenario == "monkey") {
    QStringList arguments;
    for (int i = 2; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
    monkey = mx::e2e::parseMonkeyOptions(arguments);
    if (!monkey.error.isEmpty()) return fail(monkey.error);
    if (mx::e2e::monkeyLogPath().isEmpty()) return mx::e2e::superviseMonkey(argv, monkey);
  }
  std::setlocale(LC_ALL, "C");
  const mx::e2e::IsolatedEnvironment environment;
  if (!environment.valid()) return fail("cannot create the private HOME and TMPDIR");
  if (const QString problem = mx::e2e::displayProblem(); !problem.isEmpty()) return fail(problem);
  qputenv("QT_QPA_PLATFORM", "xcb");  // a real X server, never offscreen
  QApplication app(argc, argv);
  Q_INIT_RESOURCE(resources);  // the .qrc lives in the static millexpert_gui_core
  std::setlocale(LC_NUMERIC, "C");
  QApplication::setApplicationName("MillExpert");
  QApplication::setOrganizationName("MillExpert");
  if (const QString problem = mx::e2e::screenProblem(); !problem.isEmpty()) return fail(problem);

  QElapsedTimer clock;
  clock.start();
  mx::e2e::Report report;
  try {
    if (scenario != "screenshots") {
      const QString xdotool = mx::e2e::findXdotool();
      if (xdotool.isEmpty()) return fail("xdotool is not on PATH (packaging/bootstrap.sh installs it)");
      mx::e2e::XInput input(xdotool);
      if (scenario == "check")
        mx::e2e::runCheck(report, input);
      else
        mx::e2e::runMonkey(report, xdotool, monkey, mx::e2e::monkeyLogPath());
    } else {
      mx::e2e::runScreenshots(report, QString::fromLocal8Bit(argv[2]), QApplication::arguments().mid(3));
    }
  } catch (const std::exception& e) {
    report.abort(QString("stopped: %1").arg(e.what()));
  }
  return finish(report, clock.elapsed());
}
