#include "e2e_window.h"

#include <QTest>

#include "e2e_report.h"

namespace mx::e2e {

std::unique_ptr<gui::MainWindow> showWindow() {
  auto window = std::make_unique<gui::MainWindow>();
  window->setQuiet(true);
  window->setRecoveryPolicy(gui::MainWindow::RecoveryPolicy::Discard);
  window->setGeometry(0, 0, 1920, 1080);
  window->show();
  if (!QTest::qWaitForWindowExposed(window.get(), 10000)) throw Aborted("the X server never exposed the main window");
  return window;
}

}  // namespace mx::e2e
