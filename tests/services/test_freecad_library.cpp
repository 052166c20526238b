// FreeCAD CAM tool bits and libraries (services/tool_formats/freecad_library.h): the test library
// tests/data/tool_formats/freecad (a Library/ + Bit/ layout made for these tests from FreeCAD's
// published bit structure), quantities with their units, skipped shapes, the teeth fallback, errors
// naming the file, the tool and the field, MillExpert's data in attribute.MillExpert, and round trips.
#include <QDir>
#include <QFile>

#include "services/tool_formats/freecad_library.h"
#include "services/tool_formats/freecad_quantity.h"
#include "support/project_files.h"
#include "support/tool_format_checks.h"
#include "test_registry.h"

using namespace mx;
using app::ToolSpec;

using mx::test::newTool;

namespace {

QString freeCadData(const QString& relative) {
  return QString(MX_TEST_DATA_DIR) + "/tool_formats/freecad/" + relative;
}

app::ToolImportOptions teeth(int n) {
  return app::ToolImportOptions{n};
}

const ToolSpec& toolNamed(const std::vector<ToolSpec>& tools, const QString& id) {
  for (const ToolSpec& tool : tools)
    if (tool.id == id) return tool;
  qFatal("no tool %s", qPrintable(id));
}

QStringList ids(const std::vector<ToolSpec>& tools) {
  QStringList out;
  for (const ToolSpec& tool : tools) out << tool.id;
  return out;
}

QJsonObject bitJson(const app::FreeCadExport& files, const QString& relative) {
  for (const auto& [path, bytes] : files.bits)
    if (path == relative) return QJsonDocument::fromJson(bytes).object();
  qFatal("no bit %s", qPrintable(relative));
}

// A loader over files held in memory: "Bit/<path>" of an export, or the map given.
app::FreeCadBitLoader memoryLoader(const std::map<QString, QByteArray>& bits) {
  return [bits](const QString& reference) {
    const auto found = bits.find(reference);
    if (found == bits.end()) throw app::ToolLibraryError(QString("'%1' not found").arg(reference));
    return found->second;
  };
}

app::ImportedLibrary reimport(const app::FreeCadExport& files, const app::ToolImportOptions& options = {}) {
  std::map<QString, QByteArray> bits;
  for (const auto& [path, bytes] : files.bits) bits[path.mid(QString("Bit/").size())] = bytes;
  return app::readFreeCadLibrary(files.library, files.libraryName + ".fctl", memoryLoader(bits), options);
}

app::ImportedLibrary shopLibrary() {
  return app::readFreeCadFile(freeCadData("Library/Shop.fctl"), teeth(2));
}

QByteArray bit(const QString& parameters, const QString& extra = {}) {
  return QString(R"({"version": 2, "name": "Bad", "shape": "endmill.fcstd", "parameter": {%1}%2})")
      .arg(parameters, extra)
      .toUtf8();
}

}  // namespace

class TestFreecadLibrary : public QObject {
  Q_OBJECT
 private slots:
  void quantities_data() {
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<double>("mm");  // -1: refused
    QTest::addColumn<QString>("problem");
    QTest::newRow("mm") << QJsonValue("6.000 mm") << 6.0 << "";
    QTest::newRow("mm closed up") << QJsonValue("6mm") << 6.0 << "";
    QTest::newRow("cm") << QJsonValue("0.8 cm") << 8.0 << "";
    QTest::newRow("m") << QJsonValue("0.006 m") << 0.006 * 1000.0 << "";
    QTest::newRow("inch") << QJsonValue("0.2500 in") << 0.25 * 25.4 << "";
    QTest::newRow("inch sign") << QJsonValue("0.25\"") << 0.25 * 25.4 << "";
    QTest::newRow("inch word") << QJsonValue("0.25 inch") << 0.25 * 25.4 << "";
    QTest::newRow("fraction") << QJsonValue("1/4 in") << 0.25 * 25.4 << "";
    QTest::newRow("thou") << QJsonValue("250 thou") << 250 * 0.0254 << "";
    QTest::newRow("micro sign") << QJsonValue(QString::fromUtf8("6350 \u00b5m")) << 6350 * 1e-3 << "";
    QTest::newRow("um") << QJsonValue("6350 um") << 6350 * 1e-3 << "";
    QTest::newRow("decimal comma") << QJsonValue("6,35 mm") << 6.35 << "";
    QTest::newRow("exponent") << QJsonValue("6.35e0 mm") << 6.35 << "";
    QTest::newRow("no unit: mm") << QJsonValue("6.35") << 6.35 << "";
    QTest::newRow("JSON number: mm") << QJsonValue(6.35) << 6.35 << "";
    QTest::newRow("negative") << QJsonValue("-2 mm") << -2.0 << "";
    QTest::newRow("unknown unit") << QJsonValue("6 parsec") << -1.0
                                  << "'6 parsec': unknown unit 'parsec' (a length takes mm, cm, m, "
                                     "\u00b5m, in, \", thou or ft)";
    QTest::newRow("degrees") << QJsonValue("45.00\u00b0") << -1.0 << "'45.00\u00b0' is an angle, not a length";
    QTest::newRow("deg") << QJsonValue("45 deg") << -1.0 << "'45 deg' is an angle, not a length";
    QTest::newRow("words") << QJsonValue("six mm") << -1.0 << "'six mm': not a number with a unit";
    QTest::newRow("empty") << QJsonValue("") << -1.0 << "'': not a number with a unit";
    QTest::newRow("two units") << QJsonValue("6 mm in") << -1.0 << "'6 mm in': not a number with a unit";
    QTest::newRow("overflow") << QJsonValue("1e999 mm") << -1.0 << "'1e999 mm': not a finite number";
    QTest::newRow("division by zero") << QJsonValue("1/0 in") << -1.0 << "'1/0 in': not a finite number";
    QTest::newRow("boolean") << QJsonValue(true) << -1.0 << "true: must be a length such as \"6.00 mm\"";
    QTest::newRow("long") << QJsonValue(QString(200, '6')) << -1.0 << "not a number with a unit";
  }
  void quantities() {
    QFETCH(QJsonValue, value);
    QFETCH(double, mm);
    QFETCH(QString, problem);
    const app::LengthParse parsed = app::parseFreeCadLength(value);
    if (mm == -1.0) {
      QVERIFY(!parsed.mm);
      QVERIFY2(parsed.problem.contains(problem), qPrintable(parsed.problem));
      return;
    }
    QVERIFY2(parsed.mm, qPrintable(parsed.problem));
    QCOMPARE(*parsed.mm, mm);
  }

  void shopLibraryTools() {
    const app::ImportedLibrary library = shopLibrary();
    QCOMPARE(ids(library.tools), QStringList({"T1", "T3", "T4", "T5", "T6", "T8", "T9", "T10", "T11"}));
    QCOMPARE(library.skipped.size(), std::size_t{3});
    QCOMPARE(library.skipped[0],
             (app::SkippedTool{"T2", "'5mm Drill': a drill ('drill.fcstd'), not a milling cutter"}));
    QCOMPARE(library.skipped[1], (app::SkippedTool{"T7", "'Probe': a probe ('probe.fcstd'), not a milling cutter"}));
    QCOMPARE(library.skipped[2], (app::SkippedTool{"T12", "'M8x1.25 Tap': a tap ('tap.fcstd'), not a milling cutter"}));
  }

  void shopLibraryGeometry_data() {
    QTest::addColumn<QString>("id");
    QTest::addColumn<QString>("type");
    QTest::addColumn<double>("diameter");
    QTest::addColumn<int>("teeth");
    QTest::addColumn<double>("flute_length");  // -1: none
    QTest::addColumn<double>("overall_length");
    QTest::addColumn<double>("corner_radius");  // -1: none
    QTest::newRow("endmill") << "T1"
                             << "flat end mill" << 6.0 << 3 << 20.0 << 60.0 << -1.0;
    QTest::newRow("inch bull nose") << "T3"
                                    << "bull nose end mill" << 0.25 * 25.4 << 4 << 0.75 * 25.4 << 2.5 * 25.4
                                    << 0.03 * 25.4;
    QTest::newRow("ball end, cm, Flutes as text") << "T4"
                                                  << "ball end mill" << 8.0 << 2 << 16.0 << 63.0 << -1.0;
    QTest::newRow("chamfer") << "T5"
                             << "chamfer mill" << 12.3323 << 4 << 6.35 << 30.0 << -1.0;
    QTest::newRow("v-bit: --teeth") << "T6"
                                    << "chamfer mill" << 10.0 << 2 << 1.0 << 20.0 << -1.0;
    QTest::newRow("FlatRadius: D/2 - flat") << "T8"
                                            << "bull nose end mill" << 10.0 << 4 << 25.0 << 75.0 << 2.0;
    QTest::newRow("slitting saw") << "T10"
                                  << "slot mill" << 76.2 << 24 << -1.0 << 50.0 << -1.0;
    QTest::newRow("thread mill") << "T11"
                                 << "thread mill" << 5.0 << 3 << -1.0 << 50.0 << -1.0;
  }
  void shopLibraryGeometry() {
    QFETCH(QString, id);
    QFETCH(QString, type);
    QFETCH(double, diameter);
    QFETCH(int, teeth);
    QFETCH(double, flute_length);
    QFETCH(double, overall_length);
    QFETCH(double, corner_radius);
    const ToolSpec tool = toolNamed(shopLibrary().tools, id);
    QCOMPARE(tool.type, std::optional<QString>(type));
    QCOMPARE(tool.diameter_mm, diameter);
    QCOMPARE(tool.teeth, teeth);
    QCOMPARE(tool.flute_length_mm, flute_length < 0 ? std::nullopt : std::optional<double>(flute_length));
    QCOMPARE(tool.overall_length_mm, std::optional<double>(overall_length));
    QCOMPARE(tool.corner_radius_mm, corner_radius < 0 ? std::nullopt : std::optional<double>(corner_radius));
    QVERIFY(tool.modes_x.empty() && tool.modes_y.empty());  // rigid: no modal data in the bit
    QCOMPARE(tool.origin->format, QString("freecad"));
    QCOMPARE(tool.origin->data.value("nr").toInt(), id.mid(1).toInt());
  }

  void originKeepsTheWholeBit() {
    const ToolSpec tool = toolNamed(shopLibrary().tools, "T3");
    QCOMPARE(tool.origin->data.value("path").toString(), QString("quarter_inch_Bullnose.fctb"));
    const QJsonObject bit = tool.origin->data.value("bit").toObject();
    QCOMPARE(bit.value("name").toString(), QString("1/4 in Bull Nose"));
    QCOMPARE(bit.value("parameter").toObject().value("ShankDiameter").toString(), QString("1/4 in"));
    QCOMPARE(bit.value("parameter").toObject().value("Units").toString(), QString("Imperial"));
    QVERIFY(!bit.contains("attribute"));  // the empty attribute is the writer's to add
  }

  void dynamicsFromTheMillExpertAttribute() {
    const ToolSpec tool = toolNamed(shopLibrary().tools, "T9");
    QCOMPARE(tool.helix_deg, 30.0);
    QCOMPARE(tool.Kt_N_mm2, std::optional<double>(2100.0));
    QCOMPARE(tool.Kr, std::optional<double>(0.3));
    QCOMPARE(tool.modes_x.size(), std::size_t{1});
    QCOMPARE(tool.modes_x[0].freq_Hz, 1450.0);
    QCOMPARE(tool.modes_y[0].stiffness_N_per_um, 21.0);
    QCOMPARE(tool.stickout_mm, std::optional<double>(40.0));
    QVERIFY(!tool.origin->data.value("bit").toObject().contains("attribute"));  // MillExpert's data is not origin
  }

  // FreeCAD saves an attribute it does not know as a string parameter (ToolBit.to_dict).
  void payloadSavedByFreeCadUnderParameter() {
    const QByteArray fctb = bit("\"Diameter\": \"6 mm\", \"Flutes\": 2, \"MillExpert\": \"{\\\"Kt_N_mm2\\\": 1800}\"");
    const app::ImportedLibrary library = app::readFreeCadBit(fctb, "saved.fctb");
    QCOMPARE(library.tools.at(0).Kt_N_mm2, std::optional<double>(1800.0));
    QVERIFY(
        !library.tools.at(0).origin->data.value("bit").toObject().value("parameter").toObject().contains("MillExpert"));
  }

  void withoutFlutesTheTeethOptionDecides() {
    const QString message = test::refusal([] { app::readFreeCadFile(freeCadData("Library/Shop.fctl")); });
    QCOMPARE(message, QString("60degree_Vbit.fctb: tool 'T6', parameter.Flutes: missing: the bit gives no flute "
                              "count; add \"Flutes\" to the bit or give --teeth N"));
    QCOMPARE(toolNamed(app::readFreeCadFile(freeCadData("Library/Shop.fctl"), teeth(5)).tools, "T6").teeth, 5);
    QCOMPARE(toolNamed(app::readFreeCadFile(freeCadData("Library/Shop.fctl"), teeth(5)).tools, "T1").teeth, 3);
  }

  void loneBit() {
    const QString path = freeCadData("Bit/6mm_Endmill.fctb");
    const app::ImportedLibrary library = app::readFreeCadFile(path);
    QCOMPARE(ids(library.tools), QStringList{"6mm Endmill"});
    QCOMPARE(library.tools[0].origin->data.value("path").toString(), QString("6mm_Endmill.fctb"));
    QVERIFY(!library.tools[0].origin->data.contains("nr"));
    const QByteArray nameless = bit(R"("Diameter": "6 mm", "Flutes": 2)").replace(R"("name": "Bad", )", "");
    QCOMPARE(ids(app::readFreeCadBit(nameless, "/some/where/roughing.fctb").tools), QStringList{"roughing"});
    const app::ImportedLibrary drill = app::readFreeCadFile(freeCadData("Bit/5mm_Drill.fctb"));
    QVERIFY(drill.tools.empty());
    QCOMPARE(drill.skipped.at(0).name, QString("5mm Drill"));
  }

  void shapes_data() {
    QTest::addColumn<QString>("shape");
    QTest::addColumn<QString>("shapeType");  // empty: none
    QTest::addColumn<QString>("type");       // empty: skipped
    QTest::addColumn<QString>("reason");
    QTest::newRow("endmill") << "endmill.fcstd"
                             << ""
                             << "flat end mill"
                             << "";
    QTest::newRow("shape-type wins") << "my_shape.fcstd"
                                     << "Ballend"
                                     << "ball end mill"
                                     << "";
    QTest::newRow("torus alias") << "torus.fcstd"
                                 << ""
                                 << "bull nose end mill"
                                 << "";
    QTest::newRow("v_bit") << "v_bit.fcstd"
                           << ""
                           << "chamfer mill"
                           << "";
    QTest::newRow("vbit, any case") << "VBit.FCStd"
                                    << ""
                                    << "chamfer mill"
                                    << "";
    QTest::newRow("path") << "C:\\FreeCAD\\Tools\\Shape\\dovetail.fcstd"
                          << ""
                          << "dovetail mill"
                          << "";
    QTest::newRow("fillet") << "fillet.fcstd"
                            << ""
                            << "radius mill"
                            << "";
    QTest::newRow("tapered ball nose") << "taperedballnose.fcstd"
                                       << ""
                                       << "tapered mill"
                                       << "";
    QTest::newRow("slitting saw") << ""
                                  << "SlittingSaw"
                                  << "slot mill"
                                  << "";
    QTest::newRow("drill") << "drill.fcstd"
                           << ""
                           << ""
                           << "a drill ('drill.fcstd'), not a milling cutter";
    QTest::newRow("reamer") << "reamer.fcstd"
                            << "Reamer"
                            << ""
                            << "a reamer ('reamer.fcstd'), not a milling cutter";
    QTest::newRow("turning") << "Iso_shape_C.fcstd"
                             << ""
                             << ""
                             << "a turning insert ('Iso_shape_C.fcstd'), not a milling cutter";
    QTest::newRow("custom") << "mytool.fcstd"
                            << "Custom"
                            << ""
                            << "the shape 'mytool.fcstd' is not a milling cutter FreeCAD defines";
  }
  void shapes() {
    QFETCH(QString, shape);
    QFETCH(QString, shapeType);
    QFETCH(QString, type);
    QFETCH(QString, reason);
    QJsonObject json{{"name", "B"}, {"parameter", QJsonObject{{"Diameter", "6 mm"}, {"Flutes", 2}}}};
    if (!shape.isEmpty()) json.insert("shape", shape);
    if (!shapeType.isEmpty()) json.insert("shape-type", shapeType);
    const app::ImportedLibrary library = app::readFreeCadBit(QJsonDocument(json).toJson(), "b.fctb");
    if (type.isEmpty()) {
      QVERIFY(library.tools.empty());
      QCOMPARE(library.skipped.at(0), (app::SkippedTool{"B", reason}));
      return;
    }
    QCOMPARE(library.tools.at(0).type, std::optional<QString>(type));
  }

  void bitErrors_data() {
    QTest::addColumn<QByteArray>("fctb");
    QTest::addColumn<QString>("message");
    QTest::newRow("syntax") << QByteArray("{\"shape\": ") << "x.fctb: JSON syntax error at offset 10: ";
    QTest::newRow("array") << QByteArray("[]") << "x.fctb: must be a JSON object (a FreeCAD tool bit)";
    QTest::newRow("no shape") << QByteArray(R"({"name": "Bad", "parameter": {}})")
                              << "x.fctb: tool 'Bad', shape: missing: a bit names its shape (\"endmill.fcstd\")";
    QTest::newRow("name not text") << QByteArray(R"({"name": 7, "shape": "endmill.fcstd"})")
                                   << "x.fctb: tool 'x', name: must be a string";
    QTest::newRow("parameter not object") << QByteArray(R"({"name": "Bad", "shape": "endmill", "parameter": []})")
                                          << "x.fctb: tool 'Bad', parameter: must be an object";
    QTest::newRow("unknown unit") << bit(R"("Diameter": "6 parsec", "Flutes": 2)")
                                  << "x.fctb: tool 'Bad', parameter.Diameter: '6 parsec': unknown unit 'parsec'";
    QTest::newRow("angle for a length") << bit(R"("Diameter": "6 mm", "Flutes": 2, "Length": "60°")")
                                        << "x.fctb: tool 'Bad', parameter.Length: '60°' is an angle, not a length";
    QTest::newRow("negative diameter") << bit(R"("Diameter": "-6 mm", "Flutes": 2)")
                                       << "x.fctb: tool 'Bad', parameter.Diameter: '-6 mm' (-6 mm): must be in (0, "
                                          "1000]";
    QTest::newRow("zero diameter") << bit(R"("Diameter": 0, "Flutes": 2)")
                                   << "x.fctb: tool 'Bad', parameter.Diameter: 0 (0 mm): must be in (0, 1000]";
    QTest::newRow("inch diameter too large")
        << bit(R"("Diameter": "40 in", "Flutes": 2)")
        << "x.fctb: tool 'Bad', parameter.Diameter: '40 in' (1016 mm): must be in (0, 1000]";
    QTest::newRow("no diameter") << bit(R"("Flutes": 2)")
                                 << "x.fctb: tool 'Bad', parameter.Diameter: missing: a milling bit needs its "
                                    "diameter (\"6.00 mm\")";
    QTest::newRow("fractional flutes") << bit(R"("Diameter": "6 mm", "Flutes": 2.5)")
                                       << "x.fctb: tool 'Bad', parameter.Flutes: 2.5: must be an integer in [1, 100]";
    QTest::newRow("too many flutes") << bit(R"("Diameter": "6 mm", "Flutes": "101")")
                                     << "x.fctb: tool 'Bad', parameter.Flutes: '101': must be an integer in [1, 100]";
    QTest::newRow("cutting edge above length")
        << bit(R"("Diameter": "6 mm", "Flutes": 2, "CuttingEdgeHeight": "70 mm", "Length": "60 mm")")
        << "x.fctb: tool 'Bad', parameter.CuttingEdgeHeight: 70 mm: must be <= 60 mm (Length)";
    QTest::newRow("corner radius above D/2")
        << bit(R"("Diameter": "6 mm", "Flutes": 2, "CornerRadius": "4 mm")").replace("endmill", "bullnose")
        << "x.fctb: tool 'Bad', parameter.CornerRadius: '4 mm' (4 mm): must be in [0, 3]";
    QTest::newRow("flat radius above D/2")
        << bit(R"("Diameter": "6 mm", "Flutes": 2, "FlatRadius": "4 mm")").replace("endmill", "bullnose")
        << "x.fctb: tool 'Bad', parameter.FlatRadius: '4 mm': gives a corner radius of -1 mm (Diameter/2 - "
           "FlatRadius), which must be in [0, 3]";
    QTest::newRow("payload not JSON") << bit(R"("Diameter": "6 mm", "Flutes": 2)",
                                             ", \"attribute\": {\"MillExpert\": \"{\"}")
                                      << "x.fctb: tool 'Bad', attribute.MillExpert: must be MillExpert's tool data, a "
                                         "JSON object or its text";
    QTest::newRow("payload teeth") << bit(R"("Diameter": "6 mm")", R"(, "attribute": {"MillExpert": {"teeth": 0}})")
                                   << "x.fctb: tool 'Bad', attribute.MillExpert.teeth: 0: must be an integer in [1, "
                                      "100]";
    QTest::newRow("payload flute length")
        << bit(R"("Diameter": "6 mm", "Flutes": 2)", R"(, "attribute": {"MillExpert": {"flute_length_mm": "x"}})")
        << "x.fctb: tool 'Bad', attribute.MillExpert: flute_length_mm";
    QTest::newRow("payload mode")
        << bit(R"("Diameter": "6 mm", "Flutes": 2)",
               R"(, "attribute": {"MillExpert": {"modes_x": [{"freq_Hz": -1, "damping_pct": 2, "stiffness_N_per_um": 9}]}})")
        << "x.fctb: tool 'Bad': modes_x[0].freq_Hz = -1: must be";
  }
  void bitErrors() {
    QFETCH(QByteArray, fctb);
    QFETCH(QString, message);
    const QString got = test::refusal([&] { app::readFreeCadBit(fctb, "library/x.fctb"); });
    QVERIFY2(got.startsWith(message), qPrintable(got));
  }

  void libraryErrors_data() {
    QTest::addColumn<QByteArray>("fctl");
    QTest::addColumn<QString>("message");
    QTest::newRow("syntax") << QByteArray("{") << "lib.fctl: JSON syntax error at offset 1: ";
    QTest::newRow("no tools") << QByteArray(R"({"version": 1})")
                              << "lib.fctl, tools: must be the array of the library's bits ({\"nr\", \"path\"})";
    QTest::newRow("entry not object") << QByteArray(R"({"tools": [7]})")
                                      << "lib.fctl, tools[0]: must be an object {\"nr\", \"path\"}";
    QTest::newRow("nr text") << QByteArray(R"({"tools": [{"nr": "one", "path": "a.fctb"}]})")
                             << "lib.fctl, tools[0].nr: \"one\": must be a tool number, an integer >= 0";
    QTest::newRow("nr negative") << QByteArray(R"({"tools": [{"nr": -1, "path": "a.fctb"}]})")
                                 << "lib.fctl, tools[0].nr: -1: must be a tool number, an integer >= 0";
    QTest::newRow("nr fraction") << QByteArray(R"({"tools": [{"nr": 1.5, "path": "a.fctb"}]})")
                                 << "lib.fctl, tools[0].nr: 1.5: must be a tool number, an integer >= 0";
    QTest::newRow("no path") << QByteArray(R"({"tools": [{"nr": 4}]})")
                             << "lib.fctl: tool 'T4', tools[0].path: must name the bit's file (\"endmill.fctb\")";
    QTest::newRow("missing bit") << QByteArray(R"({"tools": [{"nr": 4, "path": "gone.fctb"}]})")
                                 << "lib.fctl: tool 'T4', tools[0].path: 'gone.fctb' not found";
    QTest::newRow("bad bit") << QByteArray(R"({"tools": [{"nr": 4, "path": "bad.fctb"}]})")
                             << "bad.fctb: tool 'T4', parameter.Diameter: '6 parsec': unknown unit 'parsec'";
  }
  void libraryErrors() {
    QFETCH(QByteArray, fctl);
    QFETCH(QString, message);
    const auto loader = memoryLoader({{"bad.fctb", bit(R"("Diameter": "6 parsec", "Flutes": 2)")}});
    const QString got = test::refusal([&] { app::readFreeCadLibrary(fctl, "lib.fctl", loader); });
    QVERIFY2(got.startsWith(message), qPrintable(got));
  }

  void filesOnDiskErrors() {
    const QString missing = test::refusal([] { app::readFreeCadFile(freeCadData("Library/Missing.fctl")); });
    QVERIFY2(missing.startsWith("Missing.fctl: tool 'T2', tools[1].path: 'does_not_exist.fctb' not found: looked for "),
             qPrintable(missing));
    QVERIFY2(missing.contains("/Bit/does_not_exist.fctb"), qPrintable(missing));
    const QString bad = test::refusal([] { app::readFreeCadFile(freeCadData("Library/BadParameter.fctl")); });
    QCOMPARE(bad, QString("bad_unit.fctb: tool 'T3', parameter.Diameter: '6 parsec': unknown unit 'parsec' (a length "
                          "takes mm, cm, m, \u00b5m, in, \", thou or ft)"));
    QTemporaryDir dir;
    QFile big(dir.filePath("big.fctl"));
    QVERIFY(big.open(QIODevice::WriteOnly) && big.resize(65 * 1024 * 1024));
    big.close();
    const QString too_big = test::refusal([&] { app::readFreeCadFile(big.fileName()); });
    QVERIFY2(too_big.startsWith("big.fctl: ") && too_big.contains("64 MB"), qPrintable(too_big));
    const QString folder = test::refusal([&] { app::readFreeCadFile(dir.path()); });
    QVERIFY2(folder.endsWith(": a folder with 0 libraries in Library/: name the .fctl file"), qPrintable(folder));
  }

  // Import, export, import again: the same tools, and the second export writes the same files.
  void roundTripThroughTheFolder() {
    const app::ImportedLibrary first = shopLibrary();
    const app::FreeCadExport files = app::writeFreeCadLibrary(first.tools, "Shop copy");
    QCOMPARE(files.libraryName, QString("Shop copy"));
    QTemporaryDir dir;
    QCOMPARE(app::writeFreeCadFolder(files, dir.filePath("out")), QString());
    QVERIFY(QFile::exists(dir.filePath("out/Library/Shop copy.fctl")));
    QVERIFY(QFile::exists(dir.filePath("out/Bit/quarter_inch_Bullnose.fctb")));
    const app::ImportedLibrary second = app::readFreeCadFile(dir.filePath("out/Library/Shop copy.fctl"));
    QVERIFY(test::sameTools(second.tools, first.tools));  // the V-bit's --teeth travelled in attribute.MillExpert
    QVERIFY(test::sameTools(app::readFreeCadFile(dir.filePath("out")).tools, first.tools));  // the folder itself
    QVERIFY(second.skipped.empty());
    const app::FreeCadExport again = app::writeFreeCadLibrary(second.tools, "Shop copy");
    QCOMPARE(again.library, files.library);
    QCOMPARE(again.bits, files.bits);
  }

  void unchangedParametersKeepTheirText() {
    const app::FreeCadExport files = app::writeFreeCadLibrary(shopLibrary().tools, "Shop");
    const QJsonObject inch = bitJson(files, "Bit/quarter_inch_Bullnose.fctb");
    const QJsonObject parameters = inch.value("parameter").toObject();
    QCOMPARE(parameters.value("Diameter").toString(), QString("0.2500 in"));
    QCOMPARE(parameters.value("CornerRadius").toString(), QString("0.0300\""));
    QCOMPARE(parameters.value("ShankDiameter").toString(), QString("1/4 in"));  // not mapped: as it was
    QCOMPARE(inch.value("attribute").toObject(), QJsonObject());                // nothing to carry
    const QJsonObject vbit = bitJson(files, "Bit/60degree_Vbit.fctb");
    QVERIFY(!vbit.value("parameter").toObject().contains("Flutes"));  // the bit never had it: carried instead
    QCOMPARE(vbit.value("attribute").toObject().value("MillExpert").toString(), QString(R"({"teeth":2})"));
    QCOMPARE(vbit.value("parameter").toObject().value("CuttingEdgeAngle").toString(), QString("60.00\u00b0"));
    QCOMPARE(QJsonDocument::fromJson(files.library).object().value("tools").toArray().at(2).toObject(),
             QJsonObject({{"nr", 4}, {"path", "8mm_Ball_End.fctb"}}));
  }

  void editedValuesAreWrittenInMm() {
    std::vector<ToolSpec> tools = shopLibrary().tools;
    ToolSpec& inch = tools[1];  // T3
    inch.diameter_mm = 7.0;
    inch.teeth = 3;
    ToolSpec& flat = tools[5];  // T8, FlatRadius 3 of a 10 mm bull nose: corner 2
    flat.diameter_mm = 12.0;    // the corner stays 2: FlatRadius would now say 4
    const app::FreeCadExport files = app::writeFreeCadLibrary(tools, "Shop");
    const QJsonObject inch_parameters = bitJson(files, "Bit/quarter_inch_Bullnose.fctb").value("parameter").toObject();
    QCOMPARE(inch_parameters.value("Diameter").toString(), QString("7 mm"));
    QCOMPARE(inch_parameters.value("Flutes").toInt(), 3);
    QCOMPARE(inch_parameters.value("Length").toString(), QString("2.5000 in"));
    const QJsonObject flat_parameters =
        bitJson(files, "Bit/10mm_Bullnose_FlatRadius.fctb").value("parameter").toObject();
    QCOMPARE(flat_parameters.value("CornerRadius").toString(), QString("2 mm"));
    QVERIFY(!flat_parameters.contains("FlatRadius"));
    QVERIFY(test::sameTools(test::withoutOrigins(reimport(files).tools), test::withoutOrigins(tools)));
  }

  void dynamicsTravelInTheAttribute() {
    std::vector<ToolSpec> tools = shopLibrary().tools;
    ToolSpec& endmill = tools[0];  // T1
    endmill.modes_x = {{900.0, 4.0, 12.0, {}}};
    endmill.runout_um = std::vector<double>{0.0, 5.0, -5.0};
    endmill.helix_deg = 35.0;
    endmill.stickout_mm = 28.0;
    endmill.corner_radius_mm = 0.5;  // an endmill bit has no corner radius: carried
    endmill.Kte_N_mm = 18.5;         // the edge and axial overrides of the material
    endmill.Kre_N_mm = 0.1 + 0.2;
    endmill.Ka_N_mm2 = 1e5;
    endmill.Kae_N_mm = 0.0;
    const app::FreeCadExport files = app::writeFreeCadLibrary(tools, "Shop");
    const QJsonObject attributes = bitJson(files, "Bit/6mm_Endmill.fctb").value("attribute").toObject();
    const QJsonObject payload = QJsonDocument::fromJson(attributes.value("MillExpert").toString().toUtf8()).object();
    QCOMPARE(payload.value("helix_deg").toDouble(), 35.0);
    QCOMPARE(payload.value("stickout_mm").toDouble(), 28.0);
    QCOMPARE(payload.value("corner_radius_mm").toDouble(), 0.5);
    QCOMPARE(payload.value("modes_x").toArray().size(), 1);
    QVERIFY(!payload.contains("teeth"));  // the bit's Flutes says it
    QCOMPARE(payload.value("Kte_N_mm").toDouble(), 18.5);
    QCOMPARE(payload.value("Kre_N_mm").toDouble(), 0.1 + 0.2);
    QCOMPARE(payload.value("Ka_N_mm2").toDouble(), 1e5);
    QCOMPARE(payload.value("Kae_N_mm").toDouble(-1.0), 0.0);
    QVERIFY(test::sameTools(reimport(files).tools, tools));
    const app::ImportedLibrary again = reimport(files);
    const ToolSpec& back = toolNamed(again.tools, "T1");
    QCOMPARE(back.Kte_N_mm, endmill.Kte_N_mm);
    QCOMPARE(back.Kre_N_mm, endmill.Kre_N_mm);
    QCOMPARE(back.Ka_N_mm2, endmill.Ka_N_mm2);
    QCOMPARE(back.Kae_N_mm, endmill.Kae_N_mm);
  }

  void newToolsGetFreshBits() {
    ToolSpec face = newTool("T1", "face mill", 50.0, 5);
    face.overall_length_mm = 40.0;
    ToolSpec bull = newTool("T2", "bull nose end mill", 10.0, 4);
    bull.corner_radius_mm = 1.0;
    bull.flute_length_mm = 22.0;
    ToolSpec saw = newTool("T3", "slot mill", 63.0, 18);
    saw.flute_length_mm = 3.0;  // a slitting saw bit has no CuttingEdgeHeight: carried
    ToolSpec named = newTool("roughing 10/12", "flat end mill", 10.0, 3);
    const std::vector<ToolSpec> tools{face, bull, saw, named};
    const app::FreeCadExport files = app::writeFreeCadLibrary(tools, "");
    QCOMPARE(files.libraryName, QString("MillExpert"));
    QCOMPARE(files.bits.size(), std::size_t{4});
    QCOMPARE(files.bits[3].first, QString("Bit/roughing 10_12.fctb"));
    const QJsonObject face_bit = bitJson(files, "Bit/T1.fctb");
    QCOMPARE(face_bit.value("shape").toString(), QString("endmill.fcstd"));
    QCOMPARE(face_bit.value("shape-type").toString(), QString("Endmill"));
    QCOMPARE(face_bit.value("name").toString(), QString("T1"));
    QCOMPARE(face_bit.value("parameter").toObject(),
             QJsonObject({{"Diameter", "50 mm"}, {"Flutes", 5}, {"Length", "40 mm"}}));
    QCOMPARE(
        bitJson(files, "Bit/T2.fctb").value("parameter").toObject(),
        QJsonObject({{"Diameter", "10 mm"}, {"Flutes", 4}, {"CuttingEdgeHeight", "22 mm"}, {"CornerRadius", "1 mm"}}));
    QCOMPARE(bitJson(files, "Bit/T3.fctb").value("shape").toString(), QString("slittingsaw.fcstd"));
    const std::vector<ToolSpec> back = reimport(files).tools;
    QCOMPARE(ids(back), QStringList({"T1", "T2", "T3", "T4"}));       // numbered: a library names tools by number
    QCOMPARE(back[0].type, std::optional<QString>("flat end mill"));  // FreeCAD has no face mill shape
    QCOMPARE(back[1].corner_radius_mm, std::optional<double>(1.0));
    QCOMPARE(back[2].flute_length_mm, std::optional<double>(3.0));
    QCOMPARE(back[3].diameter_mm, 10.0);
  }

  void toolNumbers() {
    std::vector<ToolSpec> tools{newTool("T5", "flat end mill", 6, 2), newTool("drill-mill", "flat end mill", 6, 2),
                                newTool("T1", "flat end mill", 6, 2), newTool("T5", "flat end mill", 8, 2)};
    const QJsonArray entries =
        QJsonDocument::fromJson(app::writeFreeCadLibrary(tools, "n").library).object().value("tools").toArray();
    QStringList numbers;
    for (const QJsonValue entry : entries) numbers << QString::number(entry.toObject().value("nr").toInt());
    QCOMPARE(numbers, QStringList({"5", "2", "1", "3"}));  // ids first; then the lowest free numbers
  }

  void oneBitInTwoPockets() {
    const QByteArray fctl = R"({"tools": [{"nr": 1, "path": "a.fctb"}, {"nr": 2, "path": "a.fctb"}]})";
    const auto loader = memoryLoader({{"a.fctb", bit(R"("Diameter": "6 mm", "Flutes": 2)")}});
    const app::ImportedLibrary first = app::readFreeCadLibrary(fctl, "two.fctl", loader);
    const app::FreeCadExport files = app::writeFreeCadLibrary(first.tools, "two");
    QCOMPARE(files.bits.size(), std::size_t{1});
    QVERIFY(test::sameTools(reimport(files).tools, first.tools));
    std::vector<ToolSpec> edited = first.tools;
    edited[1].diameter_mm = 8.0;  // now two different bits under one name
    const app::FreeCadExport split = app::writeFreeCadLibrary(edited, "two");
    QCOMPARE(split.bits.size(), std::size_t{2});
    QCOMPARE(split.bits[1].first, QString("Bit/a-2.fctb"));
  }

  void folderWriteRefusesWhatIsNotAFile() {
    const app::FreeCadExport files = app::writeFreeCadLibrary({newTool("T1", "flat end mill", 6, 2)}, "lib");
    QTemporaryDir dir;
    QFile plain(dir.filePath("plain"));
    QVERIFY(plain.open(QIODevice::WriteOnly));
    plain.close();
    // The path is quoted, and shortened past 80 characters (a deep TMPDIR): only the reason is compared.
    QVERIFY(app::writeFreeCadFolder(files, plain.fileName()).endsWith(": not a folder"));
    QVERIFY(QDir(dir.path()).mkpath("out/Bit/T1.fctb"));
    const QString problem = app::writeFreeCadFolder(files, dir.filePath("out"));
    QVERIFY2(problem.startsWith("Bit/T1.fctb: ") && problem.contains("directory"), qPrintable(problem));
    QVERIFY(QFileInfo(dir.filePath("out/Bit/T1.fctb")).isDir());
  }
};

MX_REGISTER_TEST(TestFreecadLibrary)
#include "test_freecad_library.moc"
