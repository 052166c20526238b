#pragma once
// The application object a test runner creates: QApplication for the widget tests, QCoreApplication
// for the rest. Each domain executable links exactly one of the two definitions.
#include <QCoreApplication>
#include <memory>

namespace mx::test {
std::unique_ptr<QCoreApplication> makeTestApplication(int& argc, char** argv);
}
