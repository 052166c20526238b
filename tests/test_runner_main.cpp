// The one test main of a domain's executable:
//   <runner> UNIT [QtTest options]   runs one registered unit (the CTest entry of tests/<domain>/test_UNIT.cpp)
//   <runner> --list                  lists the units
//   <runner>                         runs every unit in turn
// Before anything runs it fixes the C locale and points HOME, the XDG folders and TMPDIR into a fresh
// temporary folder, so that no test reads or writes the developer's home or a fixed path.
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QLocale>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTextStream>
#include <QtTest>
#include <clocale>
#include <cstdio>
#include <map>
#include <string>

#include "support/test_application.h"
#include "test_registry.h"

namespace mx::test {
namespace {

std::map<std::string, TestFactory>& registry() {
  static std::map<std::string, TestFactory> units;
  return units;
}

std::string unitName(const char* source_file) {
  std::string name(source_file);
  const auto slash = name.find_last_of("/\\");
  if (slash != std::string::npos) name.erase(0, slash + 1);
  if (name.rfind("test_", 0) == 0) name.erase(0, 5);
  const auto dot = name.find('.');
  if (dot != std::string::npos) name.erase(dot);
  return name;
}

void fixLocale() {
  std::setlocale(LC_ALL, "C");
  QLocale::setDefault(QLocale::c());
}

// A private HOME, XDG folders and TMPDIR inside one temporary folder, removed at exit. Mode 0755 so
// that a service user (postgres) started by a test can enter its data folder below TMPDIR.
class IsolatedEnvironment {
 public:
  IsolatedEnvironment() : root_(QDir::tempPath() + "/mx-test-XXXXXX") {
    if (!root_.isValid()) {
      std::fprintf(stderr, "test runner: cannot create a temporary folder under %s\n", qPrintable(QDir::tempPath()));
      std::exit(3);
    }
    const QFile::Permissions open = QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner | QFile::ReadGroup |
                                    QFile::ExeGroup | QFile::ReadOther | QFile::ExeOther;
    QFile::setPermissions(root_.path(), open);
    setFolder("HOME", "home", open);
    setFolder("XDG_CONFIG_HOME", "home/.config", open);
    setFolder("XDG_DATA_HOME", "home/.local/share", open);
    setFolder("XDG_STATE_HOME", "home/.local/state", open);
    setFolder("XDG_CACHE_HOME", "home/.cache", open);
    setFolder("XDG_RUNTIME_DIR", "runtime", QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    setFolder("TMPDIR", "tmp", open);
    QStandardPaths::setTestModeEnabled(true);
  }

 private:
  void setFolder(const char* variable, const QString& relative, QFile::Permissions permissions) {
    const QString path = root_.filePath(relative);
    QDir().mkpath(path);
    QFile::setPermissions(path, permissions);
    qputenv(variable, QFile::encodeName(path));
  }

  QTemporaryDir root_;
};

int runUnit(const std::string& name, TestFactory factory, const QStringList& qtest_arguments) {
  std::unique_ptr<QObject> test = factory();
  const int failures = QTest::qExec(test.get(), qtest_arguments);
  if (failures != 0) std::fprintf(stderr, "test runner: %s: %d failure(s)\n", name.c_str(), failures);
  return failures;
}

int run(const QStringList& arguments) {
  const QString program = arguments.value(0);
  const QString first = arguments.value(1);
  if (first == "--list") {
    for (const auto& unit : registry()) std::printf("%s\n", unit.first.c_str());
    return 0;
  }
  if (first.isEmpty() || first.startsWith('-')) {
    int failures = 0;
    for (const auto& [name, factory] : registry()) failures += runUnit(name, factory, arguments);
    return failures == 0 ? 0 : 1;
  }
  const auto unit = registry().find(first.toStdString());
  if (unit == registry().end()) {
    std::fprintf(stderr, "test runner: no unit '%s' in %s (--list shows them)\n", qPrintable(first),
                 qPrintable(program));
    return 2;
  }
  QStringList qtest_arguments = arguments.mid(2);
  qtest_arguments.prepend(program);
  return runUnit(unit->first, unit->second, qtest_arguments) == 0 ? 0 : 1;
}

}  // namespace

bool registerTest(const char* source_file, TestFactory factory) {
  const bool fresh = registry().emplace(unitName(source_file), factory).second;
  if (!fresh) {
    std::fprintf(stderr, "test runner: unit of %s registered twice\n", source_file);
    std::abort();
  }
  return true;
}

}  // namespace mx::test

int main(int argc, char** argv) {
  mx::test::fixLocale();
  const mx::test::IsolatedEnvironment environment;
  QCoreApplication::setAttribute(Qt::AA_Use96Dpi, true);
  const std::unique_ptr<QCoreApplication> app = mx::test::makeTestApplication(argc, argv);
  mx::test::fixLocale();
  return mx::test::run(QCoreApplication::arguments());
}
