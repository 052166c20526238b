#include <QApplication>

#include "support/test_application.h"

namespace mx::test {
std::unique_ptr<QCoreApplication> makeTestApplication(int& argc, char** argv) {
  return std::make_unique<QApplication>(argc, argv);
}
}  // namespace mx::test
