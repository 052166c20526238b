// The shared flag readers of the CLI (cli_support.h): a number or integer flag outside its range or
// not a number exits 2 naming the flag and the range, and echoes the value shortened to 80 characters.
#include "support/cli_runner.h"
#include "support/project_files.h"
#include "test_registry.h"

namespace {

QStringList simulateWith(const QString& flag, const QString& value) {
  QStringList args{"simulate", mx::test::projectsPath("rubio2006-tool-selection.mxproj"),
                   "--tool",   "R1",
                   "--speed",  "5800",
                   "--depth",  "0.49",
                   "--feed",   "0.27"};
  const qsizetype at = args.indexOf(flag);
  if (at >= 0) {
    args[at + 1] = value;
  } else {
    args << flag << value;
  }
  return args;
}

QString cut(QChar c, int length) {
  return QString(80, c) + QChar(0x2026) + QString(" (%1 characters)").arg(length);
}

}  // namespace

class TestCliSupport : public QObject {
  Q_OBJECT
 private slots:
  void flagValuesAreEchoedShortened_data() {
    QTest::addColumn<QString>("flag");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("expected");
    QTest::newRow("short number out of range") << "--speed"
                                               << "0"
                                               << "--speed = 0: must be in [1, 100000]";
    QTest::newRow("long number out of range")
        << "--speed" << QString(200, '9') << "--speed = " + cut('9', 200) + ": must be in [1, 100000]";
    QTest::newRow("long text for a number")
        << "--depth" << QString(5000, 'z')
        << "--depth = '" + QString(80, 'z') + QChar(0x2026) + "' (5000 characters): not a finite number";
    QTest::newRow("long text for an integer")
        << "--revolutions" << QString(300, 'q')
        << "--revolutions = '" + QString(80, 'q') + QChar(0x2026) + "' (300 characters): not an integer";
    QTest::newRow("integer out of range") << "--revolutions"
                                          << "20"
                                          << "--revolutions = 20: must be an integer in [21, 100000]";
  }
  void flagValuesAreEchoedShortened() {
    QFETCH(QString, flag);
    QFETCH(QString, value);
    QFETCH(QString, expected);
    const mx::test::CliRun r = mx::test::runCli(simulateWith(flag, value));
    QCOMPARE(r.code, 2);
    QCOMPARE(r.err, "millexpert-cli: " + expected + "\n");
  }
};

MX_REGISTER_TEST(TestCliSupport)
#include "test_cli_support.moc"
