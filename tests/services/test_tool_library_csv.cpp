// Tool library import/export: CSV and JSON round trips, the documented CSV layout, and all-or-nothing
// import (a bad row changes nothing and is reported by line and column); files that are not regular or
// over the size limit are refused.
#include <QFileInfo>
#include <QJsonArray>
#include <QTemporaryDir>

#include "document/project.h"
#include "services/tool_formats/tool_library_csv.h"
#include "services/tool_formats/tool_library_transfer.h"
#include "support/hostile_files.h"
#include "support/project_files.h"
#include "test_registry.h"

using mx::app::Project;
using mx::app::ToolLibraryCsv;
using mx::app::ToolLibraryFormat;
using mx::app::ToolSpec;

using mx::test::writeText;

namespace {

QJsonArray toolsJson(const std::vector<ToolSpec>& tools) {
  Project p;
  p.tools = tools;
  return mx::app::projectToJson(p).value("tools").toArray();
}

Project rubio() {
  return mx::app::loadProject(MX_PROJECTS_DIR "/rubio2006-tool-selection.mxproj");
}

const QByteArray kHeader =
    "tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,radial_depth_mm,axis,freq_Hz,damping_pct,stiffness_N_per_um\n";

// With the optional cutter-geometry columns: pitch_deg is column 5, runout_um column 6.
const QByteArray kGeometryHeader =
    "tool_id,teeth,diameter_mm,helix_deg,pitch_deg,runout_um,Kt_N_mm2,Kr,radial_depth_mm,axis,freq_Hz,damping_pct,"
    "stiffness_N_per_um\n";

// With the optional edge and axial coefficient columns: Kte_N_mm is column 7 ... Kae_N_mm column 10.
const QByteArray kCoefficientHeader =
    "tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,Kte_N_mm,Kre_N_mm,Ka_N_mm2,Kae_N_mm,radial_depth_mm,axis,freq_Hz,"
    "damping_pct,stiffness_N_per_um\n";

// A tool overriding all four edge and axial coefficients of the material.
ToolSpec coefficientTool() {
  ToolSpec t;
  t.id = "K4";
  t.teeth = 3;
  t.diameter_mm = 12.0;
  t.helix_deg = 35.0;
  t.Kt_N_mm2 = 1800.0;
  t.Kr = 0.35;
  t.Kte_N_mm = 24.5;
  t.Kre_N_mm = 0.1 + 0.2;  // shortest round-trip text, no rounding
  t.Ka_N_mm2 = 1e5;        // the upper bounds are allowed
  t.Kae_N_mm = 0.0;        // and so is 0: an override to no axial edge force, not "the material's"
  t.modes_x = {{900.0, 2.0, 5.0, {}}, {1800.0, 1.5, 20.0, {}}};
  t.modes_y = {{950.0, 2.2, 5.5, {}}};
  return t;
}

// The window's and the CLI's import: the whole file read, then merged; "" or the reason.
QString importInto(const Project& base, const QString& path, ToolLibraryFormat format, bool replace, Project& merged) {
  try {
    const mx::app::ImportedLibrary library = mx::app::readToolLibrary(path, format, {});
    merged = mx::app::mergeImportedTools(base, library.tools, replace).project;
  } catch (const mx::app::ProjectError& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

QString exportTo(const Project& p, const QString& path, ToolLibraryFormat format) {
  try {
    mx::app::writeToolLibrary(p.tools, path, format);
  } catch (const mx::app::ProjectError& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

}  // namespace

class TestToolLibraryCsv : public QObject {
  Q_OBJECT
 private slots:
  void parsesTheDocumentedLayout() {
    QByteArray text;
    QVERIFY(ToolLibraryCsv::readFile(MX_TEST_DATA_DIR "/library/tools.csv", text).isEmpty());
    const auto file = ToolLibraryCsv::fromCsv(text);
    QVERIFY2(file.ok(), qPrintable(file.error));
    QCOMPARE(file.tools.size(), std::size_t{3});
    const ToolSpec& e16 = file.tools[0];
    QCOMPARE(e16.id, QString("E16"));
    QCOMPARE(e16.teeth, 4);
    QCOMPARE(e16.diameter_mm, 16.0);
    QCOMPARE(e16.helix_deg, 30.0);
    QVERIFY(!e16.Kt_N_mm2);
    QCOMPARE(*e16.Kr, 0.25);
    QCOMPARE(e16.modes_x.size(), std::size_t{2});
    QCOMPARE(e16.modes_x[1].freq_Hz, 1450.0);
    QCOMPARE(e16.modes_x[1].stiffness_N_per_um, 12.0);
    QCOMPARE(e16.modes_y.size(), std::size_t{1});
    QCOMPARE(e16.modes_y[0].damping_pct, 2.4);
    QCOMPARE(file.tools[1].id, QString("Ball, 10 mm"));
    QCOMPARE(*file.tools[1].Kt_N_mm2, 750.0);
    QCOMPARE(*file.tools[1].radial_depth_mm, 5.0);
    QVERIFY(file.tools[2].modes_y.empty());
    QCOMPARE(file.lines, (std::vector<int>{3, 6, 7}));
  }

  void csvRoundTripIsExact() {
    QByteArray text;
    ToolLibraryCsv::readFile(MX_TEST_DATA_DIR "/library/tools.csv", text);
    std::vector<ToolSpec> tools = rubio().tools;
    for (const ToolSpec& t : ToolLibraryCsv::fromCsv(text).tools) tools.push_back(t);
    ToolSpec rigid;  // no modes
    rigid.id = "Rigid";
    rigid.teeth = 1;
    rigid.diameter_mm = 0.1 + 0.2;
    rigid.helix_deg = -12.5;
    rigid.Kt_N_mm2 = 1e-3;
    rigid.Kr = 0.0;
    rigid.radial_depth_mm = 0.3;
    rigid.max_force_N = 250.5;
    tools.push_back(rigid);
    const auto back = ToolLibraryCsv::fromCsv(ToolLibraryCsv::toCsv(tools));
    QVERIFY2(back.ok(), qPrintable(back.error));
    QCOMPARE(toolsJson(back.tools), toolsJson(tools));
    QCOMPARE(back.tools.back().diameter_mm, 0.1 + 0.2);  // shortest round-trip text, no rounding
    QCOMPARE(*back.tools.back().max_force_N, 250.5);
  }

  // An id that starts with '#' is quoted on export: a bare one would turn its rows into comments.
  void hashIdSurvivesTheExport() {
    const auto file = ToolLibraryCsv::fromCsv(kHeader + "\"#7 rough\",2,16,30,,,,x,720,2.5,4.2\n");
    QVERIFY2(file.ok(), qPrintable(file.error));
    QCOMPARE(file.tools.at(0).id, QString("#7 rough"));
    const QByteArray csv = ToolLibraryCsv::toCsv(file.tools);
    QVERIFY(csv.contains("\n\"#7 rough\",2,16,30,"));
    const auto back = ToolLibraryCsv::fromCsv(csv);
    QVERIFY2(back.ok(), qPrintable(back.error));
    QCOMPARE(back.tools.size(), std::size_t(1));
    QCOMPARE(back.tools.at(0).id, QString("#7 rough"));
  }

  // max_force_N is an optional column: a header without it (kHeader) reads as before, one with it gives
  // the tool's F_allow; blank is no limit.
  void maxForceColumnIsOptional() {
    const QByteArray header =
        "tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,radial_depth_mm,max_force_N,axis,freq_Hz,damping_pct,"
        "stiffness_N_per_um\n";
    QCOMPARE(ToolLibraryCsv::toCsv({}), header);
    const auto with = ToolLibraryCsv::fromCsv(header + "A,2,10,0,,,,450,x,1000,2,10\nB,2,10,0,,,,,x,1000,2,10\n");
    QVERIFY2(with.ok(), qPrintable(with.error));
    QCOMPARE(*with.tools[0].max_force_N, 450.0);
    QVERIFY(!with.tools[1].max_force_N);
    const auto without = ToolLibraryCsv::fromCsv(kHeader + "A,2,10,0,,,,x,1000,2,10\n");
    QVERIFY2(without.ok(), qPrintable(without.error));
    QVERIFY(!without.tools[0].max_force_N);
    const auto bad = ToolLibraryCsv::fromCsv(header + "A,2,10,0,,,,0,x,1000,2,10\n");
    QVERIFY(!bad.ok());
    QVERIFY2(bad.error.startsWith("line 2, column 8 (max_force_N): '0' must be in (0, 1e+07]"), qPrintable(bad.error));
  }

  // pitch_deg and runout_um: ';'-separated lists, blank = uniform / none; the export writes a column only
  // when some tool has that list, and export -> import is exact.
  void geometryColumns() {
    const auto file = ToolLibraryCsv::fromCsv(kGeometryHeader +
                                              "A,4,16,30,70; 110 ;70;110,0;8;0;-5,,,,x,1000,2,10\n"
                                              "A,,,,70;110;70;110,,,,,y,1000,2,10\n"
                                              "B,2,10,0,,,,,,x,1000,2,10\n");
    QVERIFY2(file.ok(), qPrintable(file.error));
    QCOMPARE(*file.tools[0].pitch_deg, (std::vector<double>{70, 110, 70, 110}));
    QCOMPARE(*file.tools[0].runout_um, (std::vector<double>{0, 8, 0, -5}));
    QCOMPARE(file.tools[0].modes_y.size(), std::size_t{1});
    QVERIFY(!file.tools[1].pitch_deg && !file.tools[1].runout_um);

    QVERIFY(!ToolLibraryCsv::toCsv(rubio().tools).contains("pitch_deg"));
    std::vector<ToolSpec> tools = rubio().tools;
    tools[0].pitch_deg = std::vector<double>{100.1, 119.9, 140};
    QByteArray csv = ToolLibraryCsv::toCsv(tools);
    QVERIFY(csv.startsWith("tool_id,teeth,diameter_mm,helix_deg,pitch_deg,Kt_N_mm2,"));
    QVERIFY2(csv.contains(",100.1;119.9;140,"), csv.constData());
    tools[1].runout_um = std::vector<double>{0.1 + 0.2, -12};
    csv = ToolLibraryCsv::toCsv(tools);
    QVERIFY(csv.startsWith("tool_id,teeth,diameter_mm,helix_deg,pitch_deg,runout_um,Kt_N_mm2,"));
    const auto back = ToolLibraryCsv::fromCsv(csv);
    QVERIFY2(back.ok(), qPrintable(back.error));
    QCOMPARE(toolsJson(back.tools), toolsJson(tools));
    QCOMPARE(back.tools[1].runout_um->at(0), 0.1 + 0.2);
  }

  // Kte_N_mm, Kre_N_mm, Ka_N_mm2, Kae_N_mm: optional columns right after Kr, each written when some tool
  // overrides that coefficient; export -> import is exact, on every row of a tool.
  void edgeAndAxialColumnsRoundTrip() {
    std::vector<ToolSpec> tools = rubio().tools;
    tools.push_back(coefficientTool());
    const QByteArray csv = ToolLibraryCsv::toCsv(tools);
    QVERIFY2(csv.startsWith("tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,Kte_N_mm,Kre_N_mm,Ka_N_mm2,Kae_N_mm,"
                            "radial_depth_mm,max_force_N,axis,freq_Hz,damping_pct,stiffness_N_per_um\n"),
             csv.constData());
    QVERIFY2(csv.contains("\nK4,3,12,35,1800,0.35,24.5,0.30000000000000004,1e+05,0,,,y,950,2.2,5.5\n"),
             csv.constData());
    const auto back = ToolLibraryCsv::fromCsv(csv);
    QVERIFY2(back.ok(), qPrintable(back.error));
    QCOMPARE(back.tools.size(), tools.size());
    QCOMPARE(back.tools.back(), coefficientTool());
    QVERIFY(!back.tools.front().Kte_N_mm && !back.tools.front().Ka_N_mm2);  // blank: the material's
    QCOMPARE(toolsJson(back.tools), toolsJson(tools));
    QCOMPARE(ToolLibraryCsv::toCsv(back.tools), csv);

    // Only the coefficients some tool overrides get a column.
    ToolSpec axial = rubio().tools.at(0);
    axial.Ka_N_mm2 = 350.0;
    const QByteArray only = ToolLibraryCsv::toCsv({axial});
    QVERIFY2(only.startsWith("tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,Ka_N_mm2,radial_depth_mm,"),
             only.constData());
    QVERIFY(!only.contains("Kte_N_mm") && !only.contains("Kre_N_mm") && !only.contains("Kae_N_mm"));
    const auto onlyBack = ToolLibraryCsv::fromCsv(only);
    QVERIFY2(onlyBack.ok(), qPrintable(onlyBack.error));
    QCOMPARE(onlyBack.tools.at(0), axial);
  }

  // A library without any override is written exactly as before the columns existed.
  void withoutOverridesTheExportIsUnchanged() {
    QByteArray text;
    QVERIFY(ToolLibraryCsv::readFile(MX_TEST_DATA_DIR "/library/tools.csv", text).isEmpty());
    const auto file = ToolLibraryCsv::fromCsv(text);
    QVERIFY2(file.ok(), qPrintable(file.error));
    std::vector<ToolSpec> tools = file.tools;
    ToolSpec rigid;
    rigid.id = "Rigid";
    rigid.teeth = 2;
    rigid.diameter_mm = 8.0;
    rigid.max_force_N = 450.0;
    tools.push_back(rigid);
    QCOMPARE(ToolLibraryCsv::toCsv(tools),
             QByteArray("tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,radial_depth_mm,max_force_N,axis,freq_Hz,"
                        "damping_pct,stiffness_N_per_um\n"
                        "E16,4,16,30,,0.25,,,x,720,2.5,4.2\n"
                        "E16,4,16,30,,0.25,,,x,1450,1.2,12\n"
                        "E16,4,16,30,,0.25,,,y,735,2.4,4.4\n"
                        "\"Ball, 10 mm\",2,10,0,750,,5,,x,1100,1.8,2.1\n"
                        "Rigid-Y,3,20,0,,,,,x,900,2,3\n"
                        "Rigid,2,8,0,,,,450,,,,\n"));
    QCOMPARE(ToolLibraryCsv::toCsv({}), QByteArray("tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,radial_depth_mm,"
                                                   "max_force_N,axis,freq_Hz,damping_pct,stiffness_N_per_um\n"));
  }

  // A library written before the columns existed reads: the tools take the material's coefficients.
  void oldHeaderWithoutCoefficientColumnsReads_data() {
    QTest::addColumn<QByteArray>("csv");
    QTest::newRow("first layout") << kHeader + "A,2,10,0,700,0.3,,x,1000,2,10\n";
    QTest::newRow("with pitch and runout") << kGeometryHeader + "A,2,10,0,,,700,0.3,,x,1000,2,10\n";
    QTest::newRow("with max_force_N") << QByteArray(
        "tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,radial_depth_mm,"
        "max_force_N,axis,freq_Hz,damping_pct,stiffness_N_per_um\n"
        "A,2,10,0,700,0.3,,450,x,1000,2,10\n");
  }
  void oldHeaderWithoutCoefficientColumnsReads() {
    QFETCH(QByteArray, csv);
    const auto file = ToolLibraryCsv::fromCsv(csv);
    QVERIFY2(file.ok(), qPrintable(file.error));
    const ToolSpec& t = file.tools.at(0);
    QCOMPARE(t.Kt_N_mm2, std::optional(700.0));
    QCOMPARE(t.Kr, std::optional(0.3));
    QVERIFY(!t.Kte_N_mm && !t.Kre_N_mm && !t.Ka_N_mm2 && !t.Kae_N_mm);
    const QByteArray back = ToolLibraryCsv::toCsv(file.tools);  // and none is written back
    for (const char* column : {"Kte_N_mm", "Kre_N_mm", "Ka_N_mm2", "Kae_N_mm"})
      QVERIFY2(!back.contains(column), column);
  }

  // The bounds are accepted: edge forces in [0, 1e4] N/mm, the axial coefficient in [0, 1e5] N/mm^2.
  void coefficientEdgeValuesAreAccepted_data() {
    QTest::addColumn<QByteArray>("cells");  // Kte_N_mm,Kre_N_mm,Ka_N_mm2,Kae_N_mm
    QTest::addColumn<QList<double>>("values");
    const double blank = -1.0;
    QTest::newRow("zeros") << QByteArray("0,0,0,0") << QList<double>{0, 0, 0, 0};
    QTest::newRow("upper bounds") << QByteArray("10000,1e4,100000,1E4") << QList<double>{1e4, 1e4, 1e5, 1e4};
    QTest::newRow("blank") << QByteArray(",,,") << QList<double>{blank, blank, blank, blank};
    QTest::newRow("some") << QByteArray(" 12.5 ,,1e-300,") << QList<double>{12.5, blank, 1e-300, blank};
  }
  void coefficientEdgeValuesAreAccepted() {
    QFETCH(QByteArray, cells);
    QFETCH(QList<double>, values);
    const auto file = ToolLibraryCsv::fromCsv(kCoefficientHeader + "A,2,10,0,,," + cells + ",,x,1000,2,10\n" +
                                              "A,,,,,," + cells + ",,y,1000,2,10\n");  // repeated: the same
    QVERIFY2(file.ok(), qPrintable(file.error));
    const ToolSpec& t = file.tools.at(0);
    const std::optional<double> read[] = {t.Kte_N_mm, t.Kre_N_mm, t.Ka_N_mm2, t.Kae_N_mm};
    for (int i = 0; i < 4; ++i) QCOMPARE(read[i], values[i] < 0 ? std::nullopt : std::optional<double>(values[i]));
    const auto back = ToolLibraryCsv::fromCsv(ToolLibraryCsv::toCsv(file.tools));
    QVERIFY2(back.ok(), qPrintable(back.error));
    QCOMPARE(back.tools, file.tools);
  }

  void exportImportRoundTrip() {
    QTemporaryDir dir;
    const Project p = rubio();
    const QString path = dir.filePath("lib.csv");
    QCOMPARE(exportTo(p, path, ToolLibraryFormat::Csv), QString());
    Project edited;
    QCOMPARE(importInto(p, path, ToolLibraryFormat::Csv, true, edited), QString());
    QCOMPARE(toolsJson(edited.tools), toolsJson(p.tools));
    QCOMPARE(edited.material->Kt_N_mm2, 600.0);  // the rest of the project is untouched
  }

  void appendAddsToTheLibrary() {
    Project edited;
    QCOMPARE(importInto(rubio(), MX_TEST_DATA_DIR "/library/tools.csv", ToolLibraryFormat::Csv, false, edited),
             QString());
    QCOMPARE(edited.tools.size(), std::size_t{5});
    QCOMPARE(edited.tools[0].id, QString("R1"));
    QCOMPARE(edited.tools[4].id, QString("Rigid-Y"));
  }

  // An id the project already has gets the first free suffix, as library-import does.
  void appendRenamesATakenId() {
    QTemporaryDir dir;
    const QString path = writeText(dir, "r2.csv", kHeader + "R2,2,10,0,,,,x,1000,2,10\nR2-2,2,10,0,,,,x,1000,2,10\n");
    Project edited;
    QCOMPARE(importInto(rubio(), path, ToolLibraryFormat::Csv, false, edited), QString());
    QCOMPARE(edited.tools.size(), std::size_t{4});
    QCOMPARE(edited.tools[2].id, QString("R2-2"));
    QCOMPARE(edited.tools[3].id, QString("R2-2-2"));
  }

  void badRowChangesNothing_data() {
    QTest::addColumn<QByteArray>("csv");
    QTest::addColumn<bool>("replace");
    QTest::addColumn<QString>("message");
    const QByteArray good = "A,2,10,0,,,,x,1000,2,10\n";
    QTest::newRow("non-number") << kHeader + good + "A,,,,,,,y,abc,2,10\n"
                                << true << "line 3, column 9 (freq_Hz): 'abc' is not a number (number in (0, 20000])";
    QTest::newRow("out of range") << "# comment\n" + kHeader + good + "A,,,,,,,y,-3,2,10\n"
                                  << true << "line 4, column 9 (freq_Hz): '-3' must be in (0, 20000]";
    QTest::newRow("damping") << kHeader + "A,2,10,0,,,,x,1000,150,10\n"
                             << true << "line 2, column 10 (damping_pct): '150' must be in [0.001, 100)";
    QTest::newRow("stiffness") << kHeader + good + "\nB,2,10,0,,,,y,1000,2,0\n"
                               << true << "line 4, column 11 (stiffness_N_per_um): '0' must be in [0.001, 1e+06]";
    QTest::newRow("too few columns") << kHeader + good + "A,,,,,,,y,1000,2\n"
                                     << true << "line 3, column 11: the row has 10 columns, expected 11";
    QTest::newRow("too many columns") << kHeader + "A,2,10,0,,,,x,1000,2,10,7\n"
                                      << true << "line 2, column 12: the row has 12 columns, expected 11";
    QTest::newRow("unknown axis") << kHeader + good + "A,,,,,,,z,1000,2,10\n"
                                  << true << "line 3, column 8 (axis): 'z' must be x or y";
    QTest::newRow("duplicate id") << kHeader + good + "B,2,10,0,,,,x,1000,2,10\nA,2,10,0,,,,y,1000,2,10\n"
                                  << true << "line 4, column 1 (tool_id): 'A' duplicate tool id (first on line 2)";
    QTest::newRow("teeth not integer") << kHeader + "A,2.5,10,0,,,,x,1000,2,10\n"
                                       << true << "line 2, column 2 (teeth): '2.5' must be an integer in [1, 100]";
    QTest::newRow("teeth above 100") << kHeader + "A,101,10,0,,,,x,1000,2,10\n"
                                     << true << "line 2, column 2 (teeth): '101' must be an integer in [1, 100]";
    QTest::newRow("radial depth > D") << kHeader + "A,2,10,0,,,12,x,1000,2,10\n"
                                      << true << "line 2, column 7 (radial_depth_mm): '12' must be in (0, 10]";
    QTest::newRow("continuation differs")
        << kHeader + good + "A,3,,,,,,y,1000,2,10\n"
        << true << "line 3, column 2 (teeth): '3' differs from the tool's first row (line 2";
    QTest::newRow("missing id") << kHeader + good + ",2,10,0,,,,x,1000,2,10\n"
                                << true << "line 3, column 1 (tool_id): '' must be a non-empty tool id";
    QTest::newRow("blank quoted id") << kHeader + good + "\" \",2,10,0,,,,x,1000,2,10\n"
                                     << true << "line 3, column 1 (tool_id): ' ' must be a non-empty tool id";
    const QByteArray geometry = kGeometryHeader;
    QTest::newRow("pitch wrong length")
        << geometry + "A,2,10,0,90;90;180,,,,,x,1000,2,10\n"
        << true << "line 2, column 5 (pitch_deg): '90;90;180' must have one value per tooth (teeth = 2), got 3";
    QTest::newRow("pitch zero") << geometry + "A,2,10,0,0;360,,,,,x,1000,2,10\n"
                                << true << "line 2, column 5 (pitch_deg): '0;360' value 1 (0) must be in (0, 360)";
    QTest::newRow("pitch negative") << geometry + "A,2,10,0,380;-20,,,,,x,1000,2,10\n"
                                    << true
                                    << "line 2, column 5 (pitch_deg): '380;-20' value 1 (380) must be in (0, 360)";
    QTest::newRow("pitch sum 1e-5 off")
        << geometry + "A,2,10,0,180;180.00001,,,,,x,1000,2,10\n"
        << true << "line 2, column 5 (pitch_deg): '180;180.00001' must sum to 360 within 1e-06, sums to 360.00001";
    QTest::newRow("pitch not a number")
        << geometry + "A,2,10,0,180; abc,,,,,x,1000,2,10\n"
        << true << "line 2, column 5 (pitch_deg): '180; abc' value 2 ('abc') is not a number (numbers separated by ';'";
    QTest::newRow("pitch comma-separated")
        << geometry + "A,2,10,0,\"180,180\",,,,,x,1000,2,10\n"
        << true << "line 2, column 5 (pitch_deg): '180,180' value 1 ('180,180') is not a number";
    QTest::newRow("runout too large")
        << geometry + "A,2,10,0,,0;2500,,,,x,1000,2,10\n"
        << true
        << "line 2, column 6 (runout_um): '0;2500' value 2 (2500) must be in (-2500, 2500) (|runout| < D/4 = 250 * "
           "diameter_mm, diameter_mm = 10)";
    QTest::newRow("runout wrong length")
        << geometry + "A,2,10,0,,8,,,,x,1000,2,10\n"
        << true << "line 2, column 6 (runout_um): '8' must have one value per tooth (teeth = 2), got 1";
    QTest::newRow("pitch continuation differs")
        << geometry + "A,2,10,0,170;190,,,,,x,1000,2,10\nA,,,,190;170,,,,,y,1000,2,10\n"
        << true << "line 3, column 5 (pitch_deg): '190;170' differs from the tool's first row (line 2, '170;190')";
    QTest::newRow("unknown header") << QByteArray("tool_id,teeth,diam\n") << true
                                    << "line 1, column 3: unknown column 'diam'";
    QTest::newRow("reordered header") << QByteArray(
                                             "axis,tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,"
                                             "radial_depth_mm,freq_Hz,damping_pct,stiffness_N_per_um\n"
                                             "q,A,2,10,0,,,,1000,2,10\n")
                                      << true << "line 2, column 1 (axis): 'q' must be x or y";
  }
  void badCoefficientNamesTheCell_data() {
    QTest::addColumn<QByteArray>("csv");
    QTest::addColumn<bool>("replace");
    QTest::addColumn<QString>("message");
    const QByteArray h = kCoefficientHeader;
    QTest::newRow("Kte negative") << h + "A,2,10,0,,,-1,,,,,x,1000,2,10\n"
                                  << true << "line 2, column 7 (Kte_N_mm): '-1' must be in [0, 10000]";
    QTest::newRow("Kre above 1e4") << h + "A,2,10,0,,,,10000.001,,,,x,1000,2,10\n"
                                   << false << "line 2, column 8 (Kre_N_mm): '10000.001' must be in [0, 10000]";
    QTest::newRow("Ka above 1e5") << h + "A,2,10,0,,,,,100000.01,,,x,1000,2,10\n"
                                  << true << "line 2, column 9 (Ka_N_mm2): '100000.01' must be in [0, 1e+05]";
    QTest::newRow("Ka negative zero-ish") << h + "A,2,10,0,,,,,-1e-300,,,x,1000,2,10\n"
                                          << true << "line 2, column 9 (Ka_N_mm2): '-1e-300' must be in [0, 1e+05]";
    QTest::newRow("Kae above 1e4") << h + "A,2,10,0,,,,,,2e4,,x,1000,2,10\n"
                                   << true << "line 2, column 10 (Kae_N_mm): '2e4' must be in [0, 10000]";
    QTest::newRow("Kae not a number") << h + "A,2,10,0,,,,,,12 N,,x,1000,2,10\n"
                                      << true
                                      << "line 2, column 10 (Kae_N_mm): '12 N' is not a number (number in [0, 10000])";
    QTest::newRow("Kte infinite") << h + "A,2,10,0,,,inf,,,,,x,1000,2,10\n"
                                  << true << "line 2, column 7 (Kte_N_mm): 'inf' must be a finite number in [0, 10000]";
    QTest::newRow("Kre continuation differs")
        << h + "A,2,10,0,,,,5,,,,x,1000,2,10\nA,,,,,,,6,,,,y,1000,2,10\n"
        << true << "line 3, column 8 (Kre_N_mm): '6' differs from the tool's first row (line 2, '5')";
    QTest::newRow("Ka on a continuation only")
        << h + "A,2,10,0,,,,,,,,x,1000,2,10\nA,,,,,,,,300,,,y,1000,2,10\n"
        << true << "line 3, column 9 (Ka_N_mm2): '300' differs from the tool's first row (line 2, '')";
    QTest::newRow("reordered header")
        << QByteArray(
               "Kae_N_mm,tool_id,teeth,diameter_mm,helix_deg,Kt_N_mm2,Kr,radial_depth_mm,axis,freq_Hz,"
               "damping_pct,stiffness_N_per_um\n"
               "-5,A,2,10,0,,,,x,1000,2,10\n")
        << true << "line 2, column 1 (Kae_N_mm): '-5' must be in [0, 10000]";
    QTest::newRow("column given twice") << QByteArray("tool_id,Ka_N_mm2,Ka_N_mm2\n") << true
                                        << "line 1, column 3: column 'Ka_N_mm2' given twice";
  }
  void badCoefficientNamesTheCell() {
    QFETCH(QByteArray, csv);
    QFETCH(bool, replace);
    QFETCH(QString, message);
    refusedImportChangesNothing(csv, replace, message);
  }

  void badRowChangesNothing() {
    QFETCH(QByteArray, csv);
    QFETCH(bool, replace);
    QFETCH(QString, message);
    refusedImportChangesNothing(csv, replace, message);
  }

  // A row that is fine alone but not in this project (the operation's radial depth exceeds its D).
  void importIsValidatedAgainstTheProject() {
    Project p = rubio();
    p.operation->radial_immersion.reset();
    p.operation->radial_depth_mm = 12.0;
    QTemporaryDir dir;
    const QString path = writeText(dir, "small.csv", kHeader + "S8,2,8,0,,,,x,1000,2,10\n");
    Project merged;
    const QString error = importInto(p, path, ToolLibraryFormat::Csv, false, merged);
    QVERIFY2(error.startsWith("the imported tools do not fit the project: operation.radial_depth_mm = 12: must be in "
                              "(0, 8]"),
             qPrintable(error));
  }

  void jsonRoundTrip() {
    QTemporaryDir dir;
    const Project p = rubio();
    const QString path = dir.filePath("lib.json");
    QCOMPARE(exportTo(p, path, ToolLibraryFormat::Json), QString());
    QVERIFY(mx::app::loadProject(path).tools.size() == 2);  // the export is a loadable project file
    Project edited;
    QCOMPARE(importInto(p, path, ToolLibraryFormat::Json, true, edited), QString());
    QCOMPARE(toolsJson(edited.tools), toolsJson(p.tools));
  }

  // The JSON library (a project's tools) keeps the four overrides, through a file as well.
  void jsonKeepsEdgeAndAxialOverrides() {
    const auto back = ToolLibraryCsv::fromJson(ToolLibraryCsv::toJson({coefficientTool()}));
    QVERIFY2(back.ok(), qPrintable(back.error));
    QCOMPARE(back.tools.size(), std::size_t{1});
    QCOMPARE(back.tools.at(0), coefficientTool());
    QCOMPARE(ToolLibraryCsv::toJson(back.tools), ToolLibraryCsv::toJson({coefficientTool()}));

    QTemporaryDir dir;
    Project p = rubio();
    p.tools.push_back(coefficientTool());
    const QString path = dir.filePath("lib.json");
    QCOMPARE(exportTo(p, path, ToolLibraryFormat::Json), QString());
    Project edited;
    QCOMPARE(importInto(p, path, ToolLibraryFormat::Json, true, edited), QString());
    QCOMPARE(edited.tools.back(), coefficientTool());
    QCOMPARE(toolsJson(edited.tools), toolsJson(p.tools));
    // And the CSV file path the same way.
    const QString csv = dir.filePath("lib.csv");
    QCOMPARE(exportTo(p, csv, ToolLibraryFormat::Csv), QString());
    Project fromCsv;
    QCOMPARE(importInto(p, csv, ToolLibraryFormat::Csv, true, fromCsv), QString());
    QCOMPARE(toolsJson(fromCsv.tools), toolsJson(p.tools));
  }

  // An empty library exports a "tools" array, so that it imports again (as an empty library).
  void emptyLibraryJsonRoundTrip() {
    const QByteArray json = ToolLibraryCsv::toJson({});
    QVERIFY(json.contains("\"tools\": []"));
    const auto back = ToolLibraryCsv::fromJson(json);
    QVERIFY2(back.ok(), qPrintable(back.error));
    QVERIFY(back.tools.empty());
  }

  void badJsonNamesTheFieldPath_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    QTest::newRow("damping") << QString(MX_TEST_DATA_DIR "/library/bad-damping.json") << QByteArray()
                             << "tools[1].modes_x[0].damping_pct = 150: must be in [0.001, 100)";
    QTest::newRow("type") << QString() << QByteArray(R"([{"id":"A","teeth":"two"}])") << "tools[0].teeth: expected";
    QTest::newRow("no tools") << QString() << QByteArray(R"({"name":"x"})")
                              << "tools: missing (required array of tools)";
    QTest::newRow("syntax") << QString() << QByteArray("{ \"tools\": [ ") << "JSON syntax error at offset";
    const QByteArray tool = R"([{"id":"A","teeth":2,"diameter_mm":10,"helix_deg":0,"modes_x":[],"modes_y":[],)";
    QTest::newRow("Kte negative") << QString() << tool + R"("Kte_N_mm":-1}])"
                                  << "tools[0].Kte_N_mm = -1: must be in [0, 10000]";
    QTest::newRow("Kre above 1e4") << QString() << tool + R"("Kre_N_mm":10001}])"
                                   << "tools[0].Kre_N_mm = 10001: must be in [0, 10000]";
    QTest::newRow("Ka above 1e5") << QString() << tool + R"("Ka_N_mm2":100001}])"
                                  << "tools[0].Ka_N_mm2 = 100001: must be in [0, 1e+05]";
    QTest::newRow("Kae text") << QString() << tool + R"("Kae_N_mm":"3"}])"
                              << "tools[0].Kae_N_mm: expected";
  }
  void badJsonNamesTheFieldPath() {
    QFETCH(QString, path);
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    QTemporaryDir dir;
    if (path.isEmpty()) path = writeText(dir, "bad.json", json);
    Project merged;
    const QString error = importInto(rubio(), path, ToolLibraryFormat::Json, false, merged);
    QVERIFY2(error.startsWith(QFileInfo(path).fileName() + ": " + message), qPrintable(error));
    QVERIFY(merged.tools.empty());
  }

  void missingFileIsReported() {
    Project merged;
    QVERIFY(
        importInto(rubio(), "/nonexistent/lib.csv", ToolLibraryFormat::Csv, true, merged).contains("cannot be read"));
    QVERIFY(!exportTo(rubio(), "/nonexistent/dir/lib.csv", ToolLibraryFormat::Csv).isEmpty());
  }
  // Import reads only a regular file of at most 16 MB, refused before it is read; export never
  // replaces a device, FIFO or folder.
  void unreadableAndUnwritableFiles_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("read");
    QTest::addColumn<QString>("written");
    QTest::newRow("FIFO") << "fifo"
                          << "a FIFO, not a regular file: a tool library must be a regular file"
                          << "a FIFO, not a regular file";
    QTest::newRow("folder") << "folder"
                            << "a directory, not a regular file: a tool library must be a regular file"
                            << "a directory, not a regular file";
    QTest::newRow("/dev/null") << "/dev/null"
                               << "a character device, not a regular file: a tool library must be a regular file"
                               << "a character device, not a regular file";
    QTest::newRow("16 MB + 1 byte") << QString("bytes:%1").arg(16 * mx::test::kMB + 1)
                                    << "16.0 MB (16777217 bytes) is over the 16 MB limit of a tool library"
                                    << QString();
  }
  void unreadableAndUnwritableFiles() {
    QFETCH(QString, kind);
    QFETCH(QString, read);
    QFETCH(QString, written);
    QTemporaryDir dir;
    const QString path = mx::test::hostileInput(dir, kind);
    QVERIFY(!path.isEmpty());
    QByteArray bytes = "untouched";
    QCOMPARE(ToolLibraryCsv::readFile(path, bytes), path + ": " + read);
    QCOMPARE(bytes, QByteArray("untouched"));
    const QString error = ToolLibraryCsv::writeFile(path, ToolLibraryCsv::toCsv(rubio().tools));
    if (written.isEmpty()) {
      QCOMPARE(error, QString());  // a regular file is replaced
    } else {
      QCOMPARE(error, path + ": cannot write (" + written + ")");
      QVERIFY(!QFileInfo(path).isFile() || kind == "/dev/null");
    }
  }

 private:
  // An import of `csv` is refused with `message` (after the file's name) and merges nothing.
  static void refusedImportChangesNothing(const QByteArray& csv, bool replace, const QString& message) {
    QTemporaryDir dir;
    const QString path = writeText(dir, "bad.csv", csv);
    Project merged;
    const QString error = importInto(rubio(), path, ToolLibraryFormat::Csv, replace, merged);
    QVERIFY2(error.startsWith("bad.csv: " + message), qPrintable(error));
    QVERIFY(merged.tools.empty());  // nothing merged
  }
};

MX_REGISTER_TEST(TestToolLibraryCsv)
#include "test_tool_library_csv.moc"
