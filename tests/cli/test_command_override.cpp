// millexpert-cli override across controller dialects: the dialect detected or named, the program
// written back in it with only F/S words and comments changed, the refusals (unknown dialect, a program
// no dialect reads, text that is not words) with exit 2 and nothing written, and the Heidenhain AFC
// table whose AFC-LOAD is the power `point` predicts at the operating point.
#include <QFile>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <cmath>

#include "support/cli_runner.h"
#include "support/project_files.h"
#include "support/text_lines.h"
#include "test_registry.h"

namespace {
using mx::test::kSdnrp;
// A test program, or an example of projects/ ("programs/...").
QString sample(const QString& name) {
  return name.startsWith("programs/") ? QStringLiteral(MX_PROJECTS_DIR "/") + name
                                      : QStringLiteral(MX_TEST_DATA_DIR "/gcode/") + name;
}

using mx::test::fileLines;

// The line without our comment and without F / S numbers: what must not change.
QString unchangedPart(QString line) {
  line.remove(QRegularExpression(R"(( ; MX: .*| \(MX: .*\)| ; MillExpert optimised.*)$)"));
  line.remove(QRegularExpression(R"((\b[FfSs](1=)?)[-+]?[0-9.]+)"));
  return line.simplified();
}

using mx::test::writeText;
}  // namespace

class TestCommandOverride : public QObject {
  Q_OBJECT
 private slots:
  void dialects_data() {
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("dialect");
    QTest::addColumn<int>("header_lines");
    QTest::newRow("ISO") << sample("pocket_mm.nc") << "iso" << 4;
    QTest::newRow("Heidenhain") << sample("programs/pocket_mm.h") << "heidenhain" << 0;
    QTest::newRow("Sinumerik") << sample("programs/pocket_mm.mpf") << "sinumerik" << 4;
    QTest::newRow("LinuxCNC") << sample("programs/pocket_mm.ngc") << "linuxcnc" << 4;
  }
  void dialects() {
    QFETCH(QString, program);
    QFETCH(QString, dialect);
    QFETCH(int, header_lines);
    QTemporaryDir dir;
    const QString out = dir.filePath("out");
    const mx::test::CliRun r = mx::test::runCli({"override", program, kSdnrp, "--out", out});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.json["dialect"].toString(), dialect);
    QCOMPARE(r.json["dialect_source"].toString(), dialect == "iso" ? QString("default") : QString("detected"));
    QCOMPARE(r.json["changed_blocks"].toInt(), 2);
    const QStringList in = fileLines(program), res = fileLines(out);
    QCOMPARE(res.size(), in.size() + header_lines);
    int k = 0;
    for (const QString& line : res) {
      if (k < in.size() && unchangedPart(line) == unchangedPart(in[k])) {
        ++k;
        continue;
      }
      QVERIFY2(line.contains("project: cus-zuperl-sdnrp.mxproj") || line.contains("MillExpert") ||
                   line.contains("controller: ") || line.contains("date: "),
               qPrintable(line));
    }
    QCOMPARE(k, in.size());
    // Named, the same dialect gives the same program (but for the date in the header).
    const QString named = dir.filePath("named");
    const mx::test::CliRun again =
        mx::test::runCli({"override", program, kSdnrp, "--out", named, "--dialect", dialect});
    QCOMPARE(again.code, 0);
    QCOMPARE(again.json["dialect_source"].toString(), QString("named"));
    QCOMPARE(fileLines(named).size(), res.size());
  }
  void refused_data() {
    QTest::addColumn<QByteArray>("program");
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown dialect") << QByteArray("G1 X1 F100\n") << QStringList{"--dialect", "fanuc"}
                                     << "--dialect = 'fanuc': must be one of iso, heidenhain, sinumerik, linuxcnc";
    QTest::newRow("no dialect reads it") << QByteArray("Dear customer,\nG1 X1\n") << QStringList{}
                                         << "line 1: Dear customer,: not a block of a known dialect";
    QTest::newRow("two dialects") << QByteArray("0 BEGIN PGM A MM\n1 L X+1 F100\nG0 X0 S1=100\n") << QStringList{}
                                  << "line 3: G0 X0 S1=100: Siemens Sinumerik syntax (S1=)";
    QTest::newRow("a line that is not words") << QByteArray("G21\nG1 X1 F100\nG1 X2 ~~ Y1\n") << QStringList{}
                                              << "line 3, column 7: ~~: cannot be split into ISO / Fanuc words";
    QTest::newRow("Heidenhain stray character") << QByteArray("0 BEGIN PGM A MM\n1 L X+1 F100 @\n") << QStringList{}
                                                << "line 2, column 14: @: cannot be split into Heidenhain Klartext";
    QTest::newRow("AFC on an ISO program")
        << QByteArray("G1 X1 F100 S1000\n") << QStringList{"--afc", "AFC"}
        << "--afc: Heidenhain AFC needs a Heidenhain program; this one is ISO / Fanuc";
    QTest::newRow("AFC overload code") << QByteArray("0 BEGIN PGM A MM\n")
                                       << QStringList{"--afc", "AFC", "--afc-overload", "X"}
                                       << "--afc-overload = 'X': must be one of M, S, F, E, L, -";
    QTest::newRow("AFC tool table alone") << QByteArray("0 BEGIN PGM A MM\n") << QStringList{"--afc-tool", "AFC"}
                                          << "--afc-tool and --afc-overload go with --afc FILE";
  }
  void refused() {
    QFETCH(QByteArray, program);
    QFETCH(QStringList, flags);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString path = writeText(dir, "program", program);
    const QString out = dir.filePath("out");
    flags.replaceInStrings(QRegularExpression("^AFC$"), dir.filePath("AFC.TAB"));
    const mx::test::CliRun r = mx::test::runCli(QStringList{"override", path, kSdnrp, "--out", out} + flags);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY(!QFile::exists(out));
    QVERIFY(!QFile::exists(dir.filePath("AFC.TAB")));
  }
  // AFC-LOAD is the mean spindle power `point` predicts at the operating point; FMAX is the tool's
  // chip-load limit over the point's feed per tooth (0.2 / 0.137 mm in this project), rounded down.
  void afcTable() {
    QTemporaryDir dir;
    const QString afc = dir.filePath("AFC.TAB"), tool = dir.filePath("TOOL.TAB");
    const mx::test::CliRun r =
        mx::test::runCli({"override", sample("programs/pocket_mm.h"), kSdnrp, "--out", dir.filePath("out.h"), "--afc",
                          afc, "--afc-tool", tool, "--afc-overload", "F"});
    QCOMPARE(r.code, 0);
    const QJsonObject a = r.json["afc"].toObject();
    const mx::test::CliRun point = mx::test::runCli({"point", kSdnrp});
    QCOMPARE(point.code, 0);
    QVERIFY(std::abs(a["afc_load_kW"].toDouble() - point.json["mean_power_W"].toDouble() * 1e-3) < 1e-12);
    QCOMPARE(a["FMAX"].toDouble(), std::floor(100.0 * 0.2 / 0.137));
    QCOMPARE(a["fmax_limited_by"].toString(), QString("chip load"));
    QCOMPARE(a["OVLD"].toString(), QString("F"));
    QCOMPARE(a["tool_number"].toInt(), 1);  // TOOL CALL 1
    const QStringList table = fileLines(afc);
    QCOMPARE(table.value(0), QString("BEGIN AFC .TAB MM"));
    QCOMPARE(table.value(1).split(' ', Qt::SkipEmptyParts),
             QStringList({"NR", "AFC", "FMIN", "FMAX", "FIDL", "FENT", "OVLD", "POUT", "SENS", "PLC"}));
    QCOMPARE(table.value(2).split(' ', Qt::SkipEmptyParts),
             QStringList({"0", "MX_R21616B", "50", "145", "100", "100", "F", "8", "100", "0"}));
    QCOMPARE(table.value(3), QString("[END]"));
    const QStringList tools = fileLines(tool);
    QCOMPARE(tools.value(2).split(' ', Qt::SkipEmptyParts),
             QStringList({"1", "R216-16B20-040", "MX_R21616B", QString::number(a["afc_load_kW"].toDouble(), 'f', 3)}));
  }
};

MX_REGISTER_TEST(TestCommandOverride)
#include "test_command_override.moc"
