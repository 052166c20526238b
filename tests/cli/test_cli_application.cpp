// millexpert-cli's dispatch: `COMMAND --help` and `help COMMAND` print the command's usage (its flags
// with units and ranges) on stdout and exit 0, whatever else is on the line; `--help` and `help` print
// the list of commands; an unknown command exits 2, its name echoed shortened.
#include "support/cli_runner.h"
#include "test_registry.h"

namespace {

using mx::test::CliRun;
using mx::test::runCli;

}  // namespace

class TestCliApplication : public QObject {
  Q_OBJECT
 private slots:
  void commandHelp_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("usage");
    QTest::addColumn<QString>("option");
    auto row = [](const char* name, const QStringList& args, const char* usage, const char* option) {
      QTest::newRow(name) << args << QString(usage) << QString(option);
    };
    row("check", {"check", "--help"}, "Usage: millexpert-cli check [options] PROJECT", "-h, --help");
    row("simulate", {"simulate", "--help"}, "Usage: millexpert-cli simulate [options] PROJECT",
        "--speed <RPM>          Spindle speed [rpm], 1..1e5 (default: the");
    row("point -h", {"point", "-h"}, "Usage: millexpert-cli point [options] PROJECT",
        "--feed <MM_PER_TOOTH>  Feed per tooth [mm/tooth], 1e-6..10 (default:");
    row("help point", {"help", "point"}, "Usage: millexpert-cli point [options] PROJECT", "--steps <M>");
    row("lobes with a project", {"lobes", "some.mxproj", "--help"}, "Usage: millexpert-cli lobes [options] PROJECT",
        "--tool <ID>");
    row("rank with a bad flag", {"rank", "--no-such-flag", "--help"}, "Usage: millexpert-cli rank [options] PROJECT",
        "--no-simulation");
    row("weights-sweep", {"weights-sweep", "--help"}, "Usage: millexpert-cli weights-sweep [options] PROJECT",
        "--simplex");
    row("history", {"history", "--help"}, "Usage: millexpert-cli history [options] PROJECT", "--db <FILE|URL>");
    row("pareto", {"pareto", "--help"}, "Usage: millexpert-cli pareto [options] PROJECT", "-w <W1,W2,W3,W4>");
    row("control", {"control", "--help"}, "Usage: millexpert-cli control [options] PROJECT",
        "--sweep-beta <FROM:TO:STEP>");
    row("sdnrp", {"sdnrp", "--help"}, "Usage: millexpert-cli sdnrp [options] PROJECT",
        "Desired surface roughness Ra [um]");
    row("override", {"override", "--help"}, "Usage: millexpert-cli override [options] PROGRAM PROJECT", "--out <FILE>");
    row("supervise", {"supervise", "--help"}, "Usage: millexpert-cli supervise [options] PROJECT",
        "--controller <NAME>");
    row("frf-info", {"frf-info", "--help"}, "Usage: millexpert-cli frf-info [options] FILE", "--quantity <Q>");
    row("frf-fit", {"frf-fit", "--help"}, "Usage: millexpert-cli frf-fit [options] FILE", "--modes <N>");
    row("frf-export", {"frf-export", "--help"}, "Usage: millexpert-cli frf-export [options] PROJECT",
        "--output <FILE>");
    row("batch", {"batch", "--help"}, "Usage: millexpert-cli batch [options] MANIFEST", "--shard <I/N>");
    row("batch-merge", {"batch-merge", "--help"}, "Usage: millexpert-cli batch-merge [options] RESULTS.jsonl...",
        "--html <FILE>");
  }

  void commandHelp() {
    QFETCH(QStringList, args);
    QFETCH(QString, usage);
    QFETCH(QString, option);
    const CliRun run = runCli(args);
    QCOMPARE(run.code, 0);
    QVERIFY2(run.err.isEmpty(), qPrintable(run.err));
    const QString out = QString::fromUtf8(run.out);
    QCOMPARE(out.section('\n', 0, 0), usage);
    QVERIFY2(out.contains(option), qPrintable(out));
  }

  void commandList_data() {
    QTest::addColumn<QStringList>("args");
    QTest::newRow("--help") << QStringList{"--help"};
    QTest::newRow("help") << QStringList{"help"};
  }
  void commandList() {
    QFETCH(QStringList, args);
    const CliRun run = runCli(args);
    QCOMPARE(run.code, 0);
    const QString out = QString::fromUtf8(run.out);
    QVERIFY(out.startsWith("usage: millexpert-cli <command> PROJECT [options]\n"));
    for (const char* command : {"check", "lobes", "simulate", "override", "frf-info", "frf-fit", "frf-export"})
      QVERIFY2(out.contains(QString("\n  %1 ").arg(command)), command);
    QVERIFY(out.contains("millexpert-cli help <command>"));
  }

  void unknownCommands() {
    CliRun run = runCli({"help", "frobnicate"});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.startsWith("millexpert-cli: unknown command 'frobnicate'\n"), qPrintable(run.err));
    const QString name(100000, 'x');
    run = runCli({name, "p.mxproj"});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.startsWith("millexpert-cli: unknown command '" + QString(80, 'x') + QChar(0x2026) +
                                "' (100000 characters)\n"),
             qPrintable(run.err.left(300)));
    run = runCli({});
    QCOMPARE(run.code, 2);
    QVERIFY(run.err.startsWith("usage: millexpert-cli"));
  }
};

MX_REGISTER_TEST(TestCliApplication)
#include "test_cli_application.moc"
