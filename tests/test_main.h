#pragma once
// The one test main of the suite: fixes the C locale (decimal point, number formatting) before
// running a QtTest class. Use MX_TEST_MAIN(Class) at the end of each test file.
#include <QCoreApplication>
#include <QLocale>
#include <QtTest>
#include <clocale>

namespace mx::test {
inline void fixLocale() {
  std::setlocale(LC_ALL, "C");
  QLocale::setDefault(QLocale::c());
}
}  // namespace mx::test

#define MX_TEST_MAIN_WITH_APP(TestClass, AppClass)   \
  int main(int argc, char** argv) {                  \
    mx::test::fixLocale();                           \
    AppClass app(argc, argv);                        \
    app.setAttribute(Qt::AA_Use96Dpi, true);         \
    mx::test::fixLocale();                           \
    TestClass tc;                                    \
    QTEST_SET_MAIN_SOURCE_PATH                       \
    return QTest::qExec(&tc, argc, argv);            \
  }

#define MX_TEST_MAIN(TestClass) MX_TEST_MAIN_WITH_APP(TestClass, QCoreApplication)
