// Outputs never destroy inputs (cli/output_paths.h), through the real millexpert-cli: an output that
// is an input of the command (also through a symbolic or hard link, or another spelling of the path),
// another output, or an existing file that is not a regular one (FIFO, device, directory, socket) is
// refused with exit 2 and a message naming the flag, before anything is computed or written; every
// file of the folder is byte-identical afterwards and nothing is created. A regular file or a new one
// is still written.
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <QDirIterator>
#include <QFile>
#include <QMap>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <cstring>

#include "support/cli_runner.h"
#include "support/project_files.h"
#include "test_registry.h"

namespace {

using mx::test::projectsPath;

// Every entry below `root` by relative path: a regular file's bytes, else its kind (a FIFO is never
// opened) or a link's target.
QMap<QString, QByteArray> snapshot(const QString& root) {
  QMap<QString, QByteArray> entries;
  QDirIterator it(root, QDir::AllEntries | QDir::System | QDir::Hidden | QDir::NoDotAndDotDot,
                  QDirIterator::Subdirectories);
  while (it.hasNext()) {
    const QString path = it.next();
    struct stat st {};
    QByteArray what = "?";
    if (::lstat(QFile::encodeName(path).constData(), &st) == 0) {
      if (S_ISLNK(st.st_mode)) {
        what = "link to " + QFile::encodeName(QFile::symLinkTarget(path));
      } else if (S_ISREG(st.st_mode)) {
        what = mx::test::readBytes(path);
      } else if (S_ISDIR(st.st_mode)) {
        what = "directory";
      } else if (S_ISFIFO(st.st_mode)) {
        what = "fifo";
      } else if (S_ISSOCK(st.st_mode)) {
        what = "socket";
      }
    }
    entries.insert(path.mid(root.size() + 1), what);
  }
  return entries;
}

bool copyFile(const QString& from, const QString& to) {
  return QFile::copy(from, to) && QFile(to).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
}

bool makeSocket(const QString& path) {
  const QByteArray native = QFile::encodeName(path);
  sockaddr_un address{};
  if (native.size() >= static_cast<qsizetype>(sizeof address.sun_path)) return false;
  address.sun_family = AF_UNIX;
  std::memcpy(address.sun_path, native.constData(), static_cast<std::size_t>(native.size()));
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  if (fd < 0) return false;
  const bool bound = ::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
  ::close(fd);  // the socket file stays
  return bound;
}

// The inputs of every command, and each kind of file an output must not be.
bool makeWorkspace(const QTemporaryDir& dir) {
  auto at = [&](const char* name) { return dir.filePath(name); };
  return copyFile(projectsPath("rubio2006-tool-selection.mxproj"), at("p.mxproj")) &&
         copyFile(projectsPath("cus-zuperl-sdnrp.mxproj"), at("sdnrp.mxproj")) &&
         copyFile(projectsPath("rubio2006-adaptive-control.mxproj"), at("control.mxproj")) &&
         copyFile(projectsPath("landers-face-milling.mxproj"), at("landers.mxproj")) &&
         copyFile(projectsPath("rubio-pareto-case.mxproj"), at("pareto.mxproj")) &&
         copyFile(projectsPath("tap-test-example.mxproj"), at("tap.mxproj")) && QDir(dir.path()).mkdir("taps") &&
         copyFile(projectsPath("taps/T9-x.uff"), at("taps/T9-x.uff")) &&
         copyFile(projectsPath("taps/T9-y.uff"), at("taps/T9-y.uff")) &&
         copyFile(projectsPath("programs/pocket_mm.nc"), at("program.nc")) && QDir(dir.path()).mkdir("folder") &&
         ::mkfifo(QFile::encodeName(at("fifo")).constData(), 0600) == 0 && makeSocket(at("socket")) &&
         QFile::link(at("p.mxproj"), at("link")) && QFile::link(at("missing.csv"), at("dangling")) &&
         ::link(QFile::encodeName(at("p.mxproj")).constData(), QFile::encodeName(at("hard")).constData()) == 0;
}

// "@name" stands for the file `name` of the workspace.
QStringList inWorkspace(QStringList args, const QTemporaryDir& dir) {
  for (QString& a : args)
    if (a.startsWith('@')) a = dir.filePath(a.mid(1));
  return args;
}

const QStringList kSimulate{"simulate", "@p.mxproj", "--tool", "R1",     "--speed",
                            "5800",     "--depth",   "0.49",   "--feed", "0.27"};
const QStringList kOverride{"override", "@program.nc", "@sdnrp.mxproj", "--controller", "model-based"};

}  // namespace

class TestOutputPaths : public QObject {
  Q_OBJECT
 private slots:
  void refusedBeforeAnythingIsWritten_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("flag");
    QTest::addColumn<QString>("why");
    auto row = [](const char* name, const QStringList& args, const char* flag, const char* why) {
      QTest::newRow(name) << args << QString(flag) << QString(why);
    };
    row("FIFO", kSimulate + QStringList{"--csv", "@fifo"}, "--csv", "a FIFO, not a regular file");
    row("/dev/null", kSimulate + QStringList{"--csv", "/dev/null"}, "--csv", "a character device, not a regular file");
    row("directory", kSimulate + QStringList{"--csv", "@folder"}, "--csv", "a directory, not a regular file");
    row("socket", kSimulate + QStringList{"--csv", "@socket"}, "--csv", "a socket, not a regular file");
    row("project as --csv", kSimulate + QStringList{"--csv", "@p.mxproj"}, "--csv", "the same file as PROJECT");
    row("project spelt otherwise", kSimulate + QStringList{"--csv", "@folder/../p.mxproj"}, "--csv",
        "the same file as PROJECT");
    row("symlink to the project", kSimulate + QStringList{"--csv", "@link"}, "--csv", "the same file as PROJECT");
    row("hard link to the project", kSimulate + QStringList{"--csv", "@hard"}, "--csv", "the same file as PROJECT");
    row("dangling symlink", kSimulate + QStringList{"--csv", "@dangling"}, "--csv",
        "a symbolic link to a missing file");
    row("missing folder", kSimulate + QStringList{"--csv", "@nowhere/x.csv"}, "--csv", "does not exist");
    row("empty path", kSimulate + QStringList{"--csv", ""}, "--csv", "no file name");
    row("--out and --csv the same", kOverride + QStringList{"--out", "@new.nc", "--csv", "@new.nc"}, "--csv",
        "the same file as --out");
    row("program as --out", kOverride + QStringList{"--out", "@program.nc"}, "--out", "the same file as PROGRAM");
    row("project as --csv of override", kOverride + QStringList{"--out", "@new.nc", "--csv", "@sdnrp.mxproj"}, "--csv",
        "the same file as PROJECT");
    row("control --csv-continuous as --csv",
        QStringList{"control", "@control.mxproj", "--csv", "@a.csv", "--csv-continuous", "@a.csv"}, "--csv-continuous",
        "the same file as --csv");
    row("control FIFO", QStringList{"control", "@control.mxproj", "--csv-continuous", "@fifo"}, "--csv-continuous",
        "a FIFO");
    row("sdnrp project", QStringList{"sdnrp", "@sdnrp.mxproj", "--csv", "@sdnrp.mxproj"}, "--csv",
        "the same file as PROJECT");
    row("supervise /dev/null",
        QStringList{"supervise", "@landers.mxproj", "--controller", "smc2", "--csv", "/dev/null"}, "--csv",
        "a character device");
    row("frf-export over its tap test",
        QStringList{"frf-export", "@tap.mxproj", "--tool", "T9", "--source", "measured", "--output", "@taps/T9-x.uff"},
        "--output", "the same file as tools[0].frf_x");
    row("frf-export /dev/null", QStringList{"frf-export", "@p.mxproj", "--tool", "R1", "--output", "/dev/null"},
        "--output", "a character device");
    row("pareto --db project", QStringList{"pareto", "@pareto.mxproj", "--db", "@pareto.mxproj"}, "--db",
        "the same file as PROJECT");
    const QString record = R"({"tool":"R1","weights":[0.2,0.725,0.075],"q":{"speed_rpm":5800,"depth_mm":0.49,)"
                           R"("feed_mm_per_tooth":0.27},"objectives":{},"source":"operator"})";
    row("history --add-json --db FIFO", QStringList{"history", "@p.mxproj", "--db", "@fifo", "--add-json", record},
        "--db", "a FIFO");
  }

  void refusedBeforeAnythingIsWritten() {
    QFETCH(QStringList, args);
    QFETCH(QString, flag);
    QFETCH(QString, why);
    QTemporaryDir dir;
    QVERIFY(makeWorkspace(dir));
    const QMap<QString, QByteArray> before = snapshot(dir.path());
    const mx::test::CliRun r = mx::test::runCli(inWorkspace(args, dir), 20000);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(flag + " = "), qPrintable(r.err));
    QVERIFY2(r.err.contains(why), qPrintable(r.err));
    QVERIFY(r.out.isEmpty());
    const QMap<QString, QByteArray> after = snapshot(dir.path());
    QCOMPARE(after.keys(), before.keys());  // nothing created, nothing removed
    for (auto it = before.cbegin(); it != before.cend(); ++it) QVERIFY2(after[it.key()] == *it, qPrintable(it.key()));
    struct stat st {};
    QVERIFY(::stat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode));
  }

  // A long path is echoed shortened, its start kept.
  void longPathIsShortened() {
    QTemporaryDir dir;
    QVERIFY(makeWorkspace(dir));
    const QString deep = dir.filePath(QString(100, 'd') + "/x.csv");
    const mx::test::CliRun r = mx::test::runCli(inWorkspace(kSimulate, dir) + QStringList{"--csv", deep}, 20000);
    QCOMPARE(r.code, 2);
    const QString echoed = "--csv = '" + deep.left(80) + QChar(0x2026) + "' (" + QString::number(deep.size()) +
                           " characters): the folder ";
    QVERIFY2(r.err.contains(echoed), qPrintable(r.err));
  }

  // What may be written still is: a new file, an existing regular file (replaced), and a regular file
  // through a symbolic link (the link stays, its target gets the output).
  void regularAndNewFilesAreWritten_data() {
    QTest::addColumn<QString>("output");
    QTest::addColumn<QString>("written");
    QTest::newRow("new file") << "new.csv"
                              << "new.csv";
    QTest::newRow("existing regular file") << "old.csv"
                                           << "old.csv";
    QTest::newRow("link to a regular file") << "old-link"
                                            << "old.csv";
  }
  void regularAndNewFilesAreWritten() {
    QFETCH(QString, output);
    QFETCH(QString, written);
    QTemporaryDir dir;
    QVERIFY(makeWorkspace(dir));
    QFile old(dir.filePath("old.csv"));
    QVERIFY(old.open(QIODevice::WriteOnly) && old.write("stale\n") == 6);
    old.close();
    QVERIFY(QFile::link(dir.filePath("old.csv"), dir.filePath("old-link")));
    const QByteArray project = mx::test::readBytes(dir.filePath("p.mxproj"));
    const mx::test::CliRun r = mx::test::runCli(
        inWorkspace(kSimulate + QStringList{"--revolutions", "21", "--csv", "@" + output}, dir), 60000);
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QVERIFY(mx::test::readBytes(dir.filePath(written)).startsWith("time_s,x_mm,y_mm,Fx_N,Fy_N,F_N,P_W\n"));
    QCOMPARE(QFileInfo(dir.filePath("old-link")).isSymLink(), true);
    QCOMPARE(mx::test::readBytes(dir.filePath("p.mxproj")), project);
  }
};

MX_REGISTER_TEST(TestOutputPaths)
#include "test_output_paths.moc"
