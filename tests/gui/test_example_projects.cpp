// The example projects: looked for beside an install's bin/ first, then in the source tree (only for
// an executable in the build folder, as here), then the system's data folders; listed by file name
// with each project's name and description.
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTemporaryDir>

#include "example_projects.h"
#include "test_registry.h"

using namespace mx;

class TestExampleProjects : public QObject {
  Q_OBJECT
 private slots:
  void foldersAreSearchedInstallFirst() {
    const QStringList dirs = gui::exampleProjectDirs();
    QVERIFY(dirs.size() >= 3);
    QCOMPARE(dirs.at(0), QDir::cleanPath(QCoreApplication::applicationDirPath() + "/../share/millexpert/projects"));
    QCOMPARE(dirs.at(1), QDir::cleanPath(MX_PROJECTS_DIR));
    const QString data = QStandardPaths::standardLocations(QStandardPaths::GenericDataLocation).value(0);
    QVERIFY2(dirs.contains(QDir::cleanPath(data + "/millexpert/projects")), qPrintable(dirs.join(", ")));
  }

  void anInstalledExecutableNeverLooksInTheSourceTree() {
    QTemporaryDir prefix;
    QVERIFY(QDir(prefix.path()).mkpath("bin"));
    const QStringList dirs = gui::exampleProjectDirs(prefix.filePath("bin"));
    QCOMPARE(dirs.value(0), QDir::cleanPath(prefix.filePath("share/millexpert/projects")));
    QVERIFY2(!dirs.contains(QDir::cleanPath(MX_PROJECTS_DIR)), qPrintable(dirs.join(", ")));
  }

  void theSourceTreeExamplesAreListedWithTheirNames() {
    QCOMPARE(gui::exampleProjectsDir(), QDir::cleanPath(MX_PROJECTS_DIR));
    const QVector<widgets::StartEntry> examples = gui::exampleProjects();
    QVERIFY(examples.size() >= 5);
    QStringList files;
    for (const widgets::StartEntry& e : examples) {
      QVERIFY2(QFileInfo(e.path).isAbsolute() && QFileInfo::exists(e.path), qPrintable(e.path));
      QVERIFY2(!e.title.isEmpty() && !e.description.isEmpty(), qPrintable(e.path));
      files << QFileInfo(e.path).fileName();
    }
    QStringList sorted = files;
    sorted.sort();
    QCOMPARE(files, sorted);
    const qsizetype rubio = files.indexOf("rubio2006-tool-selection.mxproj");
    QVERIFY(rubio >= 0);
    QCOMPARE(examples[rubio].title, QString("Rubio, De la Sen & Ibeas (2006): tool selection R1 / R2"));
    QVERIFY(files.contains("tap-test-example.mxproj"));
  }

  void oneExampleByFileName() {
    QCOMPARE(gui::exampleProject("rubio2006-tool-selection.mxproj"),
             QDir(MX_PROJECTS_DIR).absoluteFilePath("rubio2006-tool-selection.mxproj"));
    QCOMPARE(gui::exampleProject("no-such-example.mxproj"), QString());
  }
};

MX_REGISTER_TEST(TestExampleProjects)
#include "test_example_projects.moc"
