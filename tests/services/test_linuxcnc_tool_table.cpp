// The LinuxCNC tool table (services/tool_formats/linuxcnc_tool_table.h): the test tables
// tests/data/tool_formats/linuxcnc (made for these tests after the LinuxCNC manual's "Tool Table
// Format"), words in any order and case, the units remark, flute phrases, the --teeth fallback, the
// side file that carries MillExpert's data, errors naming the file, the line, the tool and the word,
// and round trips that give back the same lines.
#include "services/tool_formats/flute_phrase.h"
#include "services/tool_formats/linuxcnc_tool_table.h"
#include "support/project_files.h"
#include "support/tool_format_checks.h"
#include "test_registry.h"

using namespace mx;
using app::ToolSpec;

using mx::test::newTool;

namespace {

QString linuxCncData(const QString& name) {
  return QString(MX_TEST_DATA_DIR) + "/tool_formats/linuxcnc/" + name;
}

app::ImportedLibrary millTable(const app::ToolImportOptions& options = {}) {
  return app::readLinuxCncToolTable(test::readBytes(linuxCncData("mill.tbl")), "mill.tbl", options,
                                    test::readBytes(linuxCncData("mill.millexpert.json")));
}

app::ImportedLibrary reimport(const app::LinuxCncExport& files, bool with_side_file = true,
                              const app::ToolImportOptions& options = {}) {
  return app::readLinuxCncToolTable(files.table, "out.tbl", options,
                                    with_side_file ? std::optional<QByteArray>(files.sideFile) : std::nullopt);
}

QStringList tableLines(const QByteArray& table) {
  return QString::fromUtf8(table).split('\n', Qt::SkipEmptyParts);
}

QString tableRefusal(const QByteArray& table, const app::ToolImportOptions& options = {},
                     const std::optional<QByteArray>& side = std::nullopt) {
  return test::refusal([&] { app::readLinuxCncToolTable(table, "tool.tbl", options, side); });
}

}  // namespace

class TestLinuxcncToolTable : public QObject {
  Q_OBJECT
 private slots:
  void flutePhrases_data() {
    QTest::addColumn<QString>("comment");
    QTest::addColumn<int>("count");  // 0: none, -1: refused
    QTest::newRow("3FL") << "6mm carbide endmill 3FL" << 3;
    QTest::newRow("3 FL") << "3 FL" << 3;
    QTest::newRow("3 fl lower") << "ball 3 fl" << 3;
    QTest::newRow("3 flutes") << "10mm roughing endmill 3 flutes" << 3;
    QTest::newRow("3flutes") << "3flutes" << 3;
    QTest::newRow("3-flute") << "3-flute, 12mm" << 3;
    QTest::newRow("3 - FLUTE") << "3 - FLUTE" << 3;
    QTest::newRow("4 Flt") << "4 Flt TiAlN" << 4;
    QTest::newRow("2 fluted") << "2 fluted" << 2;
    QTest::newRow("5 teeth") << "face mill 5 teeth" << 5;
    QTest::newRow("1 tooth") << "fly cutter 1 tooth" << 1;
    QTest::newRow("10FL") << "50mm shell mill 10FL" << 10;
    QTest::newRow("after a slash") << "6mm/3FL" << 3;
    QTest::newRow("twice, agreeing") << "3FL (3 flutes)" << 3;
    QTest::newRow("no phrase") << "6mm endmill" << 0;
    QTest::newRow("empty") << "" << 0;
    QTest::newRow("flute length") << "flute length 20" << 0;
    QTest::newRow("decimal") << "1.5FL" << 0;
    QTest::newRow("glued to a letter") << "x3FL" << 0;
    QTest::newRow("flats") << "3 flats" << 0;
    QTest::newRow("zero") << "0FL" << -1;
    QTest::newRow("above 100") << "120 flutes" << -1;
    QTest::newRow("disagreeing") << "2FL, 3 flutes" << -1;
  }
  void flutePhrases() {
    QFETCH(QString, comment);
    QFETCH(int, count);
    const app::FlutePhrase phrase = app::flutePhrase(comment);
    if (count < 0) {
      QVERIFY(!phrase.count);
      QVERIFY(!phrase.problem.isEmpty());
      return;
    }
    QCOMPARE(phrase.count, count == 0 ? std::nullopt : std::optional<int>(count));
    QVERIFY(phrase.problem.isEmpty());
  }

  void phraseProblems() {
    QCOMPARE(app::flutePhrase("0FL").problem, QString("'0FL': must be an integer in [1, 100]"));
    QCOMPARE(app::flutePhrase("2FL, 3 flutes").problem, QString("'2FL' and '3 flutes' disagree"));
    QCOMPARE(app::withFluteCount("6mm 3FL, 3 flutes", 4), QString("6mm 4FL, 4 flutes"));
    QCOMPARE(app::withFluteCount("6mm endmill", 4), QString("6mm endmill"));
  }

  void millTableTools_data() {
    QTest::addColumn<QString>("id");
    QTest::addColumn<double>("diameter");
    QTest::addColumn<int>("teeth");
    QTest::newRow("every word") << "T1" << 6.0 << 3;
    QTest::newRow("4 flutes") << "T2" << 10.0 << 4;
    QTest::newRow("lower case, +z") << "T3" << 12.0 << 2;
    QTest::newRow("tabs, teeth") << "T4" << 50.0 << 5;
    QTest::newRow("count from the side file") << "T7" << 8.0 << 2;
  }
  void millTableTools() {
    QFETCH(QString, id);
    QFETCH(double, diameter);
    QFETCH(int, teeth);
    const app::ImportedLibrary library = millTable();
    QCOMPARE(library.tools.size(), std::size_t{5});
    QVERIFY(library.skipped.empty());
    for (const ToolSpec& tool : library.tools) {
      if (tool.id != id) continue;
      QCOMPARE(tool.diameter_mm, diameter);
      QCOMPARE(tool.teeth, teeth);
      QCOMPARE(tool.origin->format, QString("linuxcnc"));
      return;
    }
    QFAIL("no such tool");
  }

  void originKeepsTheLine() {
    const ToolSpec t3 = millTable().tools[2];
    const QJsonObject data = t3.origin->data;
    QCOMPARE(data.value("T").toDouble(), 3.0);
    QCOMPARE(data.value("P").toDouble(), 5.0);
    QCOMPARE(data.value("words").toArray(), QJsonArray({"t3", "p5", "d12", "z+70"}));
    QCOMPARE(data.value("comment").toString(), QString("12mm ball, 2-flute"));
    QCOMPARE(data.value("units").toString(), QString("mm"));
    QVERIFY(!t3.overall_length_mm && !t3.stickout_mm);  // Z is a gauge length, not a tool length
  }

  void sideFileCarriesModalData() {
    const ToolSpec t1 = millTable().tools[0];
    QCOMPARE(t1.helix_deg, 30.0);
    QCOMPARE(t1.Kt_N_mm2, std::optional<double>(2100.0));
    QCOMPARE(t1.modes_x.size(), std::size_t{1});
    QCOMPARE(t1.modes_x[0].freq_Hz, 1450.0);
    QCOMPARE(t1.modes_y[0].damping_pct, 2.8);
    QCOMPARE(t1.type, std::optional<QString>("flat end mill"));
    QCOMPARE(t1.stickout_mm, std::optional<double>(30.0));
    const app::ImportedLibrary rigid = app::readLinuxCncToolTable(test::readBytes(linuxCncData("mill.tbl")), "mill.tbl",
                                                                  app::ToolImportOptions{2}, std::nullopt);
    QVERIFY(rigid.tools[0].modes_x.empty() && rigid.tools[0].modes_y.empty());
    QCOMPARE(rigid.tools[0].teeth, 3);
  }

  void withoutACountTheTeethOptionDecides() {
    const QByteArray table = test::readBytes(linuxCncData("mill.tbl"));
    QCOMPARE(test::refusal([&] { app::readLinuxCncToolTable(table, "mill.tbl", {}, std::nullopt); }),
             QString("mill.tbl: tool 'T7', line 8, comment: no flute count: state it in the comment (\"3FL\", "
                     "\"3 flutes\") or give --teeth N"));
    const app::ImportedLibrary library = app::readLinuxCncToolTable(table, "mill.tbl", {4}, std::nullopt);
    QCOMPARE(library.tools[4].teeth, 4);
    QCOMPARE(library.tools[0].teeth, 3);  // the comment's count wins over --teeth
  }

  void inchTable() {
    const app::ImportedLibrary library =
        app::readLinuxCncToolTable(test::readBytes(linuxCncData("inch.tbl")), "inch.tbl", {}, std::nullopt);
    QCOMPARE(library.tools.size(), std::size_t{2});
    QCOMPARE(library.tools[0].diameter_mm, 0.25 * 25.4);
    QCOMPARE(library.tools[1].diameter_mm, 0.5 * 25.4);
    QCOMPARE(library.tools[1].teeth, 4);
    QCOMPARE(library.tools[0].origin->data.value("units").toString(), QString("inch"));
    const app::LinuxCncExport files = app::writeLinuxCncToolTable(library.tools);
    QCOMPARE(tableLines(files.table),
             QStringList({"; LinuxCNC tool table written by MillExpert (docs/tool-libraries.md)", "; units: inch",
                          "T1 P1 D0.25 Z1.5 ;1/4 endmill 2FL", "T2 P2 D0.5 Z2.125 ;1/2 endmill 4 FL"}));
    QVERIFY(test::sameTools(reimport(files).tools, library.tools));
  }

  // Import, export, import again: the same tools; each line as it was; the second export the same bytes.
  void roundTrip() {
    const app::ImportedLibrary first = millTable();
    const app::LinuxCncExport files = app::writeLinuxCncToolTable(first.tools);
    const QStringList lines = tableLines(files.table);
    QCOMPARE(lines.mid(2),
             QStringList({"T1 P1 X0 Y0 Z50.5 A0 B0 C0 U0 V0 W0 D6 I0 J0 Q0 ;6mm carbide endmill 3FL",
                          "T2 P2 Z62.25 D10.0 ;10mm roughing endmill 4 flutes", "t3 p5 d12 z+70 ;12mm ball, 2-flute",
                          "T4 P4 D50 Z80 ;face mill 5 teeth", "T7 P7 D8 Z55 ;8mm endmill from the drawer"}));
    const app::ImportedLibrary second = reimport(files);
    QVERIFY(test::sameTools(second.tools, first.tools));
    const app::LinuxCncExport again = app::writeLinuxCncToolTable(second.tools);
    QCOMPARE(again.table, files.table);
    QCOMPARE(again.sideFile, files.sideFile);
  }

  void editedToolsUpdateTheirLine() {
    std::vector<ToolSpec> tools = millTable().tools;
    tools[0].teeth = 4;
    tools[1].diameter_mm = 9.5;
    tools[4].teeth = 3;  // T7: no phrase in its comment; the side file says it
    tools[2].id = "T12";
    const app::LinuxCncExport files = app::writeLinuxCncToolTable(tools);
    const QStringList lines = tableLines(files.table);
    QCOMPARE(lines[2], QString("T1 P1 X0 Y0 Z50.5 A0 B0 C0 U0 V0 W0 D6 I0 J0 Q0 ;6mm carbide endmill 4FL"));
    QCOMPARE(lines[3], QString("T2 P2 Z62.25 D9.5 ;10mm roughing endmill 4 flutes"));
    QCOMPARE(lines[4], QString("T12 p5 d12 z+70 ;12mm ball, 2-flute"));
    QCOMPARE(lines[6], QString("T7 P7 D8 Z55 ;8mm endmill from the drawer"));
    const std::vector<ToolSpec> back = reimport(files).tools;
    QVERIFY(test::sameTools(test::withoutOrigins(back), test::withoutOrigins(tools)));
    QCOMPARE(reimport(files, false, {2}).tools[4].teeth, 2);  // without the side file: --teeth
  }

  void newToolsGetALine() {
    ToolSpec endmill = newTool("T3", "flat end mill", 10.0, 3);
    endmill.flute_length_mm = 22.0;
    endmill.overall_length_mm = 72.0;
    endmill.modes_x = {{1100.0, 3.0, 15.0, {}}};
    ToolSpec named = newTool("roughing 2FL", "bull nose end mill", 16.0, 4);
    named.corner_radius_mm = 1.0;
    const app::LinuxCncExport files = app::writeLinuxCncToolTable({endmill, named});
    QCOMPARE(tableLines(files.table).mid(1), QStringList({"; units: mm", "T3 P3 D10 ;T3, flat end mill, 3 flutes",
                                                          "T1 P1 D16 ;roughing 4FL, bull nose end mill"}));
    const std::vector<ToolSpec> back = reimport(files).tools;
    QCOMPARE(back[0].flute_length_mm, std::optional<double>(22.0));
    QCOMPARE(back[0].overall_length_mm, std::optional<double>(72.0));
    QCOMPARE(back[0].modes_x.size(), std::size_t{1});
    QCOMPARE(back[0].type, std::optional<QString>("flat end mill"));
    QCOMPARE(back[1].id, QString("T1"));
    QCOMPARE(back[1].corner_radius_mm, std::optional<double>(1.0));
    QCOMPARE(back[1].teeth, 4);
    const QJsonObject side = QJsonDocument::fromJson(files.sideFile).object();
    QCOMPARE(side.value("tools").toArray().at(1).toObject().value("id").toString(), QString("T1"));
  }

  void mixedUnitsAreWrittenInMm() {
    std::vector<ToolSpec> tools = millTable().tools;
    const app::ImportedLibrary inch =
        app::readLinuxCncToolTable(test::readBytes(linuxCncData("inch.tbl")), "inch.tbl", {}, std::nullopt);
    ToolSpec quarter = inch.tools[0];
    quarter.id = "T20";
    tools.push_back(quarter);
    const QStringList lines = tableLines(app::writeLinuxCncToolTable(tools).table);
    QCOMPARE(lines[1], QString("; units: mm"));
    QCOMPARE(lines.last(), QString("T20 P1 D6.35 Z38.1 ;1/4 endmill 2FL"));
    ToolSpec inch_only = inch.tools[1];
    inch_only.diameter_mm = 12.0;
    const app::LinuxCncExport files = app::writeLinuxCncToolTable({inch_only, newTool("T9", "flat end mill", 6.0, 2)});
    const QStringList inch_lines = tableLines(files.table);
    QCOMPARE(inch_lines[1], QString("; units: inch"));  // the units of the only table the tools came from
    QVERIFY2(
        inch_lines[2].startsWith("T2 P2 D0.472440944881889") && inch_lines[2].endsWith(" Z2.125 ;1/2 endmill 4 FL"),
        qPrintable(inch_lines[2]));
    QVERIFY2(
        inch_lines[3].startsWith("T9 P9 D0.23622047244094") && inch_lines[3].endsWith(" ;T9, flat end mill, 2 flutes"),
        qPrintable(inch_lines[3]));
    const std::vector<ToolSpec> back = reimport(files).tools;
    QVERIFY(back[0].diameter_mm == 12.0);  // exactly: the inch text is one that reads back as 12 mm
    QCOMPARE(back[1].diameter_mm, 6.0);
  }

  void remarksBlankLinesAndCrLf() {
    const QByteArray table = "; first remark\r\n\r\n   \r\n;T P D\r\nT5 P1 D4 ;4mm 2FL\r\n   ; indented remark\r\n";
    const app::ImportedLibrary library = app::readLinuxCncToolTable(table, "tool.tbl", {}, std::nullopt);
    QCOMPARE(library.tools.size(), std::size_t{1});
    QCOMPARE(library.tools[0].id, QString("T5"));
    QCOMPARE(library.tools[0].origin->data.value("comment").toString(), QString("4mm 2FL"));
    const QByteArray no_comment = "T5 P1 D4\n";
    const ToolSpec tool = app::readLinuxCncToolTable(no_comment, "tool.tbl", {3}, std::nullopt).tools.at(0);
    QVERIFY(!tool.origin->data.contains("comment"));
    QCOMPARE(tableLines(app::writeLinuxCncToolTable({tool}).table).last(), QString("T5 P1 D4"));
  }

  void errors_data() {
    QTest::addColumn<QByteArray>("table");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown word") << QByteArray("T1 P1 D6 K5 ;2FL")
                                  << "tool.tbl, line 1, 'K5': not a tool table word (T, P, X, Y, Z, A, B, C, U, V, "
                                     "W, D, I, J, Q, then a number)";
    QTest::newRow("letter alone") << QByteArray("T1 P1 D ;2FL")
                                  << "tool.tbl, line 1, 'D': must be the letter and a number";
    QTest::newRow("text number") << QByteArray("T1 P1 Dsix ;2FL")
                                 << "tool.tbl, line 1, 'Dsix': must be the letter and a number";
    QTest::newRow("fractional T") << QByteArray("T1.5 P1 D6 ;2FL")
                                  << "tool.tbl, line 1, 'T1.5': must be the letter and an integer";
    QTest::newRow("overflow") << QByteArray("T1 P1 D1e999 ;2FL")
                              << "tool.tbl, line 1, 'D1e999': must be the letter and a number";
    QTest::newRow("repeated word") << QByteArray("T1 P1 D6 d7 ;2FL") << "tool.tbl, line 1, 'd7': repeats the D word";
    QTest::newRow("old style") << QByteArray("1 1 0.5 6 ;2FL") << "tool.tbl, line 1, '1': not a tool table word";
    QTest::newRow("no T") << QByteArray("; remark\nP1 D6 ;2FL") << "tool.tbl, line 2: no tool number (a T word)";
    QTest::newRow("negative T") << QByteArray("T-1 P1 D6 ;2FL") << "tool.tbl, line 1, T: -1: must be an integer >= 0";
    QTest::newRow("negative P") << QByteArray("T1 P-2 D6 ;2FL") << "tool.tbl, line 1, P: -2: must be an integer >= 0";
    QTest::newRow("no D") << QByteArray("T1 P1 Z50 ;2FL")
                          << "tool.tbl: tool 'T1', line 1, D: missing: the cutter's diameter (D word)";
    QTest::newRow("zero D") << QByteArray("T1 P1 D0 ;2FL")
                            << "tool.tbl: tool 'T1', line 1, D: 0 mm: must be in (0, 1000]";
    QTest::newRow("negative D") << QByteArray("T4 P1 D-0.02 ;2FL")
                                << "tool.tbl: tool 'T4', line 1, D: -0.02 mm: must be in (0, 1000]";
    QTest::newRow("inch D too large") << QByteArray(";units: inch\nT4 P1 D40 ;2FL")
                                      << "tool.tbl: tool 'T4', line 2, D: 40 inch (1016 mm): must be in (0, 1000]";
    QTest::newRow("unknown units") << QByteArray("; units: furlong\nT1 P1 D6 ;2FL")
                                   << "tool.tbl, line 1: units 'furlong': must be mm or inch";
    QTest::newRow("two units") << QByteArray("; units: mm\n; UNITS=inch\nT1 P1 D6 ;2FL")
                               << "tool.tbl, line 2: declares other units than an earlier line";
    QTest::newRow("zero flutes") << QByteArray("T1 P1 D6 ;0FL")
                                 << "tool.tbl: tool 'T1', line 1, comment: '0FL': must be an integer in [1, 100]";
    QTest::newRow("disagreeing flutes") << QByteArray("T1 P1 D6 ;2FL 3 flutes")
                                        << "tool.tbl: tool 'T1', line 1, comment: '2FL' and '3 flutes' disagree";
    QTest::newRow("no count") << QByteArray("T1 P1 D6")
                              << "tool.tbl: tool 'T1', line 1, comment: no flute count: state it in the comment";
  }
  void errors() {
    QFETCH(QByteArray, table);
    QFETCH(QString, message);
    const QString got = tableRefusal(table);
    QVERIFY2(got.startsWith(message), qPrintable(got));
  }

  void badTeethOptionAndSideFile() {
    QCOMPARE(tableRefusal("T1 P1 D6", {0}), QString("tool.tbl: tool 'T1', --teeth: must be an integer in [1, 100]"));
    const QByteArray side =
        R"({"format": "millexpert-tool-dynamics", "version": 1, "tools": [{"id": "T1", "teeth": 0}]})";
    QCOMPARE(tableRefusal("T1 P1 D6", {}, side),
             QString("tool.millexpert.json: tool 'T1', teeth: 0: must be an integer in [1, 100]"));
    const QByteArray bad_mode = R"({"format": "millexpert-tool-dynamics", "version": 1, "tools": [{"id": "T1",
        "modes_x": [{"freq_Hz": 0, "damping_pct": 2, "stiffness_N_per_um": 9}]}]})";
    const QString mode = tableRefusal("T1 P1 D6 ;2FL", {}, bad_mode);
    QVERIFY2(mode.startsWith("tool.millexpert.json: tool 'T1': modes_x[0].freq_Hz = 0: must be"), qPrintable(mode));
    const QString syntax = tableRefusal("T1 P1 D6 ;2FL", {}, QByteArray("{"));
    QVERIFY2(syntax.startsWith("tool.millexpert.json: JSON syntax error"), qPrintable(syntax));
  }

  void atMostAThousandTools() {
    QByteArray table;
    for (int t = 1; t <= 1001; ++t) table += QString("T%1 P%1 D6 ;2FL\n").arg(t).toUtf8();
    QCOMPARE(tableRefusal(table), QString("tool.tbl, line 1001: more than 1000 tools: LinuxCNC reads at most 1000"));
    table.chop(QString("T1001 P1001 D6 ;2FL\n").size());
    QCOMPARE(app::readLinuxCncToolTable(table, "tool.tbl", {}, std::nullopt).tools.size(), std::size_t{1000});
  }
};

MX_REGISTER_TEST(TestLinuxcncToolTable)
#include "test_linuxcnc_tool_table.moc"
