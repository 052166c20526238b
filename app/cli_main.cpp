// millexpert-cli: every engine capability with JSON on stdout. Exit codes: 0 ok, 1 failed, 2 bad input.
#include <QCoreApplication>
#include <clocale>

#include "cli/cli_application.h"
#include "mx_version.h"

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  QCoreApplication::setApplicationName("millexpert-cli");
  QCoreApplication::setApplicationVersion(mx::app::kVersion);
  std::setlocale(LC_NUMERIC, "C");
  return mx::app::runCli(QCoreApplication::arguments());
}
