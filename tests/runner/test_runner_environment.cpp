// The test runner's isolation: HOME, the XDG folders, TMPDIR, QSettings and the application data
// folders all lie inside one fresh "mx-test-*" folder, so no test touches the user's home or a fixed path.
#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

#include "test_registry.h"

namespace {

// The enclosing "mx-test-*" folder of `path` (which need not exist yet), or "" when there is none.
QString rootOf(QString path) {
  path = QDir::cleanPath(path);
  while (!QFileInfo(path).fileName().startsWith("mx-test-")) {
    const QString parent = QFileInfo(path).path();
    if (parent == path) return {};
    path = parent;
  }
  return path;
}

}  // namespace

class TestRunnerEnvironment : public QObject {
  Q_OBJECT
 private slots:
  void everyWritableFolderIsPrivate_data() {
    QTest::addColumn<QString>("path");
    QTest::newRow("HOME") << QDir::homePath();
    QTest::newRow("TMPDIR") << QDir::tempPath();
    QTest::newRow("XDG_CONFIG_HOME") << qEnvironmentVariable("XDG_CONFIG_HOME");
    QTest::newRow("XDG_DATA_HOME") << qEnvironmentVariable("XDG_DATA_HOME");
    QTest::newRow("XDG_STATE_HOME") << qEnvironmentVariable("XDG_STATE_HOME");
    QTest::newRow("XDG_CACHE_HOME") << qEnvironmentVariable("XDG_CACHE_HOME");
    QTest::newRow("XDG_RUNTIME_DIR") << qEnvironmentVariable("XDG_RUNTIME_DIR");
    QTest::newRow("QSettings") << QSettings("MillExpertTest", "millexpert-test").fileName();
    QTest::newRow("AppDataLocation") << QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    QTest::newRow("GenericDataLocation") << QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation);
    QTest::newRow("TempLocation") << QStandardPaths::writableLocation(QStandardPaths::TempLocation);
  }
  void everyWritableFolderIsPrivate() {
    QFETCH(QString, path);
    QVERIFY(!path.isEmpty());
    const QString root = rootOf(path);
    QVERIFY2(!root.isEmpty(), qPrintable(path));
    QCOMPARE(root, rootOf(QDir::homePath()));
  }

  void theFoldersExistAndAreWritable() {
    for (const QString& path : {QDir::homePath(), QDir::tempPath(), qEnvironmentVariable("XDG_RUNTIME_DIR")}) {
      const QFileInfo info(path);
      QVERIFY2(info.isDir() && info.isWritable(), qPrintable(path));
    }
    // A service user (postgres) must be able to enter TMPDIR; XDG_RUNTIME_DIR stays private.
    QVERIFY(QFileInfo(QDir::tempPath()).permission(QFile::ExeOther));
    QVERIFY(!QFileInfo(qEnvironmentVariable("XDG_RUNTIME_DIR")).permission(QFile::ReadOther));
  }

  void testModeIsOn() { QVERIFY(QStandardPaths::isTestModeEnabled()); }
};

MX_REGISTER_TEST(TestRunnerEnvironment)
#include "test_runner_environment.moc"
