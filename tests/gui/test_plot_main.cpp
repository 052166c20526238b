// millexpert-plot's output: OUT is refused with exit 2, before anything is drawn, when it is one of the
// curve files it reads or not a regular file (/dev/null, a FIFO, a folder); the inputs keep their bytes.
#include <sys/stat.h>

#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>

#include "support/project_files.h"
#include "test_registry.h"

class TestPlotMain : public QObject {
  Q_OBJECT
 private slots:
  void outputThatWouldDestroyAnInput_data() {
    QTest::addColumn<QString>("out");  // "@name": a file of the test's folder
    QTest::addColumn<QString>("why");
    QTest::newRow("a curve file") << "@lobes.json"
                                  << "the same file as a curve file";
    QTest::newRow("/dev/null") << "/dev/null"
                               << "a character device, not a regular file";
    QTest::newRow("FIFO") << "@fifo"
                          << "a FIFO, not a regular file";
    QTest::newRow("folder") << "@folder"
                            << "a directory, not a regular file";
  }
  void outputThatWouldDestroyAnInput() {
    QFETCH(QString, out);
    QFETCH(QString, why);
    const QString exe = QFileInfo(MX_CLI_PATH).absoluteDir().filePath("gui/millexpert-plot");
    QVERIFY2(QFileInfo::exists(exe), qPrintable(exe + " not built: build the target millexpert-plot"));
    QTemporaryDir dir;
    const QString curve = dir.filePath("lobes.json");
    QFile file(curve);
    const QByteArray json = R"({"speed_rpm":[1000,2000],"blim_mm":[1.5,2.5]})";
    QVERIFY(file.open(QIODevice::WriteOnly) && file.write(json) == json.size());
    file.close();
    QVERIFY(QDir(dir.path()).mkdir("folder"));
    QVERIFY(::mkfifo(QFile::encodeName(dir.filePath("fifo")).constData(), 0600) == 0);
    if (out.startsWith('@')) out = dir.filePath(out.mid(1));
    QProcess plot;
    plot.setProcessEnvironment([] {
      QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
      env.insert("QT_QPA_PLATFORM", "offscreen");
      return env;
    }());
    plot.start(exe, {out, curve + "=R1"});
    QVERIFY(plot.waitForFinished(30000));
    QCOMPARE(plot.exitCode(), 2);
    const QString message = QString::fromUtf8(plot.readAllStandardError());
    QVERIFY2(message.contains("millexpert-plot: OUT = '") && message.contains(why), qPrintable(message));
    QCOMPARE(mx::test::readBytes(curve), json);
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot),
             (QStringList{"fifo", "folder", "lobes.json"}));
  }
};

MX_REGISTER_TEST(TestPlotMain)
#include "test_plot_main.moc"
