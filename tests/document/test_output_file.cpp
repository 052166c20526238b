// Where the application writes (document/output_file.h): a regular file or a new file in an existing
// writable folder is written atomically; a device, FIFO, directory, socket, a link to nowhere or a new
// file in a missing folder is refused before anything is written, and left as it was. saveProject (the
// GUI's Save As) refuses the same.
#include <sys/stat.h>

#include <QDir>
#include <QTemporaryDir>

#include "document/output_file.h"
#include "document/project.h"
#include "document/shortened_text.h"
#include "support/hostile_files.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx::app;

class TestOutputFile : public QObject {
  Q_OBJECT
 private slots:
  void refused_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("problem");
    QTest::newRow("/dev/null") << "/dev/null"
                               << "a character device, not a regular file";
    QTest::newRow("FIFO") << "fifo"
                          << "a FIFO, not a regular file";
    QTest::newRow("folder") << "folder"
                            << "a directory, not a regular file";
    QTest::newRow("link to nowhere") << "dangling"
                                     << "a symbolic link to a missing file";
    QTest::newRow("missing folder") << "missing/x.csv"
                                    << "the folder %1 does not exist";
    QTest::newRow("empty") << ""
                           << "no file name";
  }
  void refused() {
    QFETCH(QString, kind);
    QFETCH(QString, problem);
    QTemporaryDir dir;
    QString path = mx::test::hostileInput(dir, kind);
    if (kind == "dangling") QVERIFY(QFile::link(dir.filePath("nowhere"), path = dir.filePath("dangling")));
    if (kind.contains('/') && !kind.startsWith('/')) path = dir.filePath(kind);
    if (kind.isEmpty()) path.clear();
    const QStringList before = QDir(dir.path()).entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot);
    const QString expected = problem.contains("%1") ? problem.arg(quoted(dir.filePath("missing"))) : problem;
    QCOMPARE(outputFileProblem(path), expected);
    QCOMPARE(writeFileAtomically(path, "data\n"), expected);
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot), before);
    struct stat st {};
    QVERIFY(::stat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode));
  }

  void regularAndNewFilesAreWritten() {
    QTemporaryDir dir;
    const QString fresh = dir.filePath("new.txt");
    QCOMPARE(outputFileProblem(fresh), QString());
    QCOMPARE(writeFileAtomically(fresh, "one\n"), QString());
    QCOMPARE(mx::test::readBytes(fresh), QByteArray("one\n"));
    QCOMPARE(writeFileAtomically(fresh, "two\n"), QString());  // an existing regular file is replaced
    QCOMPARE(mx::test::readBytes(fresh), QByteArray("two\n"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"new.txt"});
  }

  void saveAsRefusesADevice() {
    const Project p = loadProject(mx::test::projectsPath("rubio2006-tool-selection.mxproj"));
    try {
      saveProject(p, "/dev/null");
      QFAIL("saved onto /dev/null");
    } catch (const ProjectError& e) {
      QCOMPARE(QString::fromStdString(e.what()),
               QString("/dev/null: cannot write project file: a character device, not a regular file"));
    }
    struct stat st {};
    QVERIFY(::stat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode));
  }
};

MX_REGISTER_TEST(TestOutputFile)
#include "test_output_file.moc"
