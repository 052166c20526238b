// Fusion 360 tool libraries (services/tool_formats/fusion_library.h): the geometry, flutes, type and
// presets of milling cutters in mm and in inches, the unit from the tool, its expressions or the
// library, the skipped tools, the origin record kept whole, round trips through both containers, the
// dynamics payload, and the refusals (file, tool and field named; bad, oversized and bomb archives).
// The libraries in tests/data/tool_formats/fusion were written here after Fusion's published record
// structure (docs/tool-libraries.md).
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>

#include "document/project.h"
#include "services/tool_formats/fusion_library.h"
#include "services/tool_formats/zip_archive.h"
#include "test_registry.h"

using mx::app::CuttingPresetSpec;
using mx::app::FusionContainer;
using mx::app::ImportedLibrary;
using mx::app::SkippedTool;
using mx::app::ToolLibraryError;
using mx::app::ToolSpec;

Q_DECLARE_METATYPE(FusionContainer)

namespace {

const QString kDataDir = QStringLiteral(MX_TEST_DATA_DIR "/tool_formats/fusion/");

QByteArray fileBytes(const QString& name) {
  QFile file(kDataDir + name);
  if (!file.open(QIODevice::ReadOnly)) qFatal("missing test file %s", qPrintable(name));
  return file.readAll();
}

ImportedLibrary read(const QString& name) {
  return mx::app::readFusionLibrary(fileBytes(name), name);
}

QJsonArray dataOf(const QByteArray& json) {
  return QJsonDocument::fromJson(json).object().value("data").toArray();
}

const ToolSpec& toolById(const ImportedLibrary& library, const QString& id) {
  for (const ToolSpec& tool : library.tools)
    if (tool.id == id) return tool;
  qFatal("no tool %s", qPrintable(id));
}

// The message of the refusal, or "accepted".
QString refusal(const QByteArray& bytes, const QString& name = "tools.json") {
  try {
    mx::app::readFusionLibrary(bytes, name);
  } catch (const ToolLibraryError& e) {
    return QString::fromUtf8(e.what());
  }
  return "accepted";
}

// A library of one metric tool T7 with `geometry` and the record's other keys from `extra`.
QByteArray oneTool(const QJsonObject& geometry, const QJsonObject& extra = {}) {
  QJsonObject tool{{"description", "test cutter"},
                   {"geometry", geometry},
                   {"post-process", QJsonObject{{"number", 7}}},
                   {"type", "flat end mill"},
                   {"unit", "millimeters"}};
  for (auto it = extra.begin(); it != extra.end(); ++it) tool.insert(it.key(), it.value());
  return QJsonDocument(QJsonObject{{"data", QJsonArray{tool}}}).toJson();
}

const QJsonObject kGoodGeometry{{"DC", 10}, {"NOF", 3}, {"LCF", 30}, {"OAL", 75}};

QJsonObject withKey(QJsonObject object, const QString& key, const QJsonValue& value) {
  if (value.isUndefined()) {
    object.remove(key);
  } else {
    object.insert(key, value);
  }
  return object;
}

bool near(double a, double b) {
  return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b));
}

}  // namespace

class TestFusionLibrary : public QObject {
  Q_OBJECT
 private slots:
  void metricGeometryIsMapped() {
    const ImportedLibrary library = read("metric.json");
    QCOMPARE(library.tools.size(), std::size_t{3});
    QVERIFY(library.skipped.empty());
    QCOMPARE(library.tools[0].id, QString("T2"));
    QCOMPARE(library.tools[1].id, QString("T4"));
    QCOMPARE(library.tools[2].id, QString("6 mm ball end mill"));  // post-process.number 0: the description

    const ToolSpec& flat = library.tools[0];
    QCOMPARE(flat.type, std::optional<QString>("flat end mill"));
    QCOMPARE(flat.teeth, 3);
    QCOMPARE(flat.diameter_mm, 10.0);
    QCOMPARE(flat.flute_length_mm, std::optional(35.0));
    QCOMPARE(flat.overall_length_mm, std::optional(75.0));
    QCOMPARE(flat.stickout_mm, std::optional(50.0));
    QCOMPARE(flat.corner_radius_mm, std::optional(0.0));
    QCOMPARE(flat.helix_deg, 0.0);
    QVERIFY(flat.modes_x.empty() && flat.modes_y.empty());  // no payload: a rigid tool

    const ToolSpec& bull = library.tools[1];
    QCOMPARE(bull.type, std::optional<QString>("bull nose end mill"));
    QCOMPARE(bull.teeth, 4);
    QCOMPARE(bull.diameter_mm, 12.0);
    QCOMPARE(bull.corner_radius_mm, std::optional(1.0));
    QCOMPARE(bull.helix_deg, 45.0);  // geometry.HA
    QCOMPARE(bull.stickout_mm, std::optional(40.0));

    const ToolSpec& ball = library.tools[2];
    QCOMPARE(ball.corner_radius_mm, std::optional(3.0));
    QCOMPARE(ball.stickout_mm, std::nullopt);
  }

  void presetsAreMappedWithTheirValues() {
    const ImportedLibrary library = read("metric.json");
    const std::vector<CuttingPresetSpec>& presets = library.tools[0].cutting_data;
    QCOMPARE(presets.size(), std::size_t{2});
    const CuttingPresetSpec& aluminium = presets[0];
    QCOMPARE(aluminium.name, QString("Aluminium"));
    QCOMPARE(aluminium.speed_rpm, std::optional(12000.0));
    QCOMPARE(aluminium.surface_speed_m_min, std::optional(376.99111843077515));
    QCOMPARE(aluminium.feed_per_tooth_mm, std::optional(0.1));
    QCOMPARE(aluminium.feed_mm_min, std::optional(3600.0));
    QCOMPARE(aluminium.axial_depth_mm, std::optional(5.0));
    QCOMPARE(aluminium.radial_depth_mm, std::optional(2.5));
    // Fusion's other preset keys stay with the preset; the mapped ones do not.
    QCOMPARE(aluminium.unknown.value("v_f_plunge").toDouble(), 200.0);
    QCOMPARE(aluminium.unknown.value("tool-coolant").toString(), QString("flood"));
    QCOMPARE(aluminium.unknown.value("guid").toString(), QString("0b6c2d7e-1f3a-4c55-9a0e-2d4f6a8b1c03"));
    for (const char* key : {"name", "n", "v_c", "f_z", "v_f", "stepdown", "stepover"})
      QVERIFY2(!aluminium.unknown.contains(key), key);

    const CuttingPresetSpec& steel = presets[1];  // stepdown and stepover 0: not used by Fusion
    QCOMPARE(steel.axial_depth_mm, std::nullopt);
    QCOMPARE(steel.radial_depth_mm, std::nullopt);
    QCOMPARE(steel.unknown.value("stepdown").toDouble(), 0.0);
    QCOMPARE(steel.unknown.value("use-stepdown").toBool(), false);

    const CuttingPresetSpec& unnamed = library.tools[2].cutting_data.at(0);  // "name": "" in the file
    QCOMPARE(unnamed.name, QString("Preset 1"));
    QCOMPARE(unnamed.speed_rpm, std::optional(15000.0));
    QCOMPARE(unnamed.surface_speed_m_min, std::nullopt);
  }

  void theWholeRecordIsKeptAsOrigin() {
    const ImportedLibrary library = read("metric.json");
    const QJsonArray records = dataOf(fileBytes("metric.json"));
    for (std::size_t i = 0; i < library.tools.size(); ++i) {
      QVERIFY(library.tools[i].origin.has_value());
      QCOMPARE(library.tools[i].origin->format, QString("fusion"));
      QCOMPARE(library.tools[i].origin->data, records.at(static_cast<qsizetype>(i)).toObject());
    }
    const QJsonObject& holder = library.tools[0].origin->data.value("holder").toObject();
    QCOMPARE(holder.value("product-id").toString(), QString("BT40-ER32-70"));
  }

  void inchLibraryConvertsToMillimetres() {
    const ImportedLibrary library = read("inch.json");
    QCOMPARE(library.tools.size(), std::size_t{3});
    const ToolSpec& half = toolById(library, "T1");
    QCOMPARE(half.diameter_mm, 12.7);  // 0.5 in, exactly
    QCOMPARE(half.flute_length_mm, std::optional(31.75));
    QCOMPARE(half.overall_length_mm, std::optional(76.2));
    QCOMPARE(half.stickout_mm, std::optional(38.1));
    QCOMPARE(toolById(library, "T5").diameter_mm, 6.35);
    QCOMPARE(toolById(library, "T5").corner_radius_mm, std::optional(3.175));
    QCOMPARE(toolById(library, "T7").diameter_mm, 9.525);
    QCOMPARE(toolById(library, "T7").corner_radius_mm, std::optional(0.79375));

    const CuttingPresetSpec& preset = half.cutting_data.at(0);
    QCOMPARE(preset.speed_rpm, std::optional(3000.0));
    QCOMPARE(preset.feed_mm_min, std::optional(609.6));    // 24 in/min
    QCOMPARE(preset.axial_depth_mm, std::optional(6.35));  // 0.25 in
    QVERIFY(near(*preset.radial_depth_mm, 1.27));          // 0.05 in
    QVERIFY(near(*preset.feed_per_tooth_mm, 0.0508));      // 0.002 in
    // 392.7 ft/min is the surface speed of 12.7 mm at 3000 rpm: pi D n / 1000 m/min.
    QVERIFY(near(*preset.surface_speed_m_min, std::numbers::pi * 12.7 * 3000.0 / 1000.0));
    QCOMPARE(preset.unknown.value("v_f_plunge").toDouble(), 8.0);  // unmapped keys stay in the file's unit
  }

  void unitSources_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("id");
    QTest::addColumn<double>("diameter");
    QTest::newRow("tool unit, mm") << "metric.json"
                                   << "T2" << 10.0;
    QTest::newRow("tool unit, inches") << "inch.json"
                                       << "T1" << 12.7;
    QTest::newRow("expressions.tool_unit") << "inch_expressions.json"
                                           << "T3" << 12.7;
    QTest::newRow("library unit") << "library_unit.json"
                                  << "T3" << 12.7;
    QTest::newRow("tool unit over the library's") << "library_unit.json"
                                                  << "T4" << 10.0;
  }
  void unitSources() {
    QFETCH(QString, file);
    QFETCH(QString, id);
    QFETCH(double, diameter);
    QCOMPARE(toolById(read(file), id).diameter_mm, diameter);
  }

  void theLibraryUnitIsWrittenIntoTheOrigin() {
    const ImportedLibrary library = read("library_unit.json");
    const ToolSpec& tool = toolById(library, "T3");
    QCOMPARE(tool.origin->data.value("unit").toString(), QString("inches"));
    const QByteArray json = mx::app::writeFusionLibrary({tool}, FusionContainer::Json);
    QCOMPARE(dataOf(json).at(0).toObject().value("unit").toString(), QString("inches"));
    QCOMPARE(mx::app::readFusionLibrary(json, "again.json").tools.at(0).diameter_mm, 12.7);
  }

  void nonMillingToolsAreSkippedWithTheReason() {
    const ImportedLibrary library = read("mixed.json");
    QCOMPARE(library.tools.size(), std::size_t{2});
    QCOMPARE(library.tools[0].id, QString("T8"));
    QCOMPARE(library.tools[0].type, std::optional<QString>("chamfer mill"));
    QCOMPARE(library.tools[1].id, QString("T9"));
    QCOMPARE(library.tools[1].teeth, 5);
    QCOMPARE(library.tools[1].cutting_data.at(0).feed_per_tooth_mm, std::optional(0.15));
    const std::vector<SkippedTool> expected{
        {"BT40 ER32 holder", "'holder' (a holder without a cutter)"},
        {"T10", "'drill' (a drill, not a milling cutter)"},
        {"T11", "'spot drill' (a drill, not a milling cutter)"},
        {"T12", "'tap right hand' (a tap, not a milling cutter)"},
        {"T20", "'probe' (a probe, not a cutting tool)"},
        {"T30", "'turning general' (a lathe tool, not a milling cutter)"},
        {"T40", "'laser cutter' (not a milling cutter)"},
    };
    QCOMPARE(library.skipped, expected);
  }

  void roundTrip_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<FusionContainer>("container");
    for (const char* file :
         {"metric.json", "inch.json", "inch_expressions.json", "library_unit.json", "mixed.json", "metric.tools"}) {
      QTest::addRow("%s as JSON", file) << file << FusionContainer::Json;
      QTest::addRow("%s as .tools", file) << file << FusionContainer::Zipped;
    }
  }
  void roundTrip() {
    QFETCH(QString, file);
    QFETCH(FusionContainer, container);
    const ImportedLibrary first = read(file);
    const QByteArray exported = mx::app::writeFusionLibrary(first.tools, container);
    QCOMPARE(mx::app::looksLikeZip(exported), container == FusionContainer::Zipped);
    const ImportedLibrary again = mx::app::readFusionLibrary(exported, "again");
    QVERIFY(again.skipped.empty());  // only the milling cutters were imported, and exported
    QCOMPARE(again.tools, first.tools);
    QCOMPARE(mx::app::writeFusionLibrary(again.tools, container), exported);
  }

  void anExportReturnsTheOriginalRecords() {
    const QJsonArray original = dataOf(fileBytes("metric.json"));
    const QJsonArray exported = dataOf(mx::app::writeFusionLibrary(read("metric.json").tools, FusionContainer::Json));
    QCOMPARE(exported.size(), original.size());
    for (qsizetype i = 0; i < exported.size(); ++i) {
      QJsonObject record = exported.at(i).toObject();
      QVERIFY(record.value(mx::app::kFusionPayloadKey).isObject());
      record.remove(mx::app::kFusionPayloadKey);
      QCOMPARE(record, original.at(i).toObject());
    }
  }

  void theZippedLibraryIsTheSameLibrary() {
    QCOMPARE(read("metric.tools").tools.size(), std::size_t{3});
    QCOMPARE(read("metric.tools").tools, read("metric.json").tools);
    // The container is told by the bytes, not by the name.
    QCOMPARE(mx::app::readFusionLibrary(fileBytes("metric.tools"), "library.json").tools.size(), std::size_t{3});
    QCOMPARE(mx::app::readFusionLibrary(fileBytes("metric.json"), "library.tools").tools.size(), std::size_t{3});
    const QByteArray zipped = mx::app::writeFusionLibrary(read("metric.json").tools, FusionContainer::Zipped);
    const QByteArray json = mx::app::writeFusionLibrary(read("metric.json").tools, FusionContainer::Json);
    QCOMPARE(mx::app::readSingleJsonEntry(zipped), json);
  }

  void editedValuesAreWrittenInTheToolsUnit() {
    ImportedLibrary library = read("metric.json");
    ToolSpec& bull = library.tools[1];
    bull.diameter_mm = 16.0;
    bull.cutting_data.push_back({"Brass", 8000.0, std::nullopt, 0.08, std::nullopt, 2.0, std::nullopt, {}});
    ImportedLibrary inch = read("inch.json");
    inch.tools[0].diameter_mm = 25.4;
    inch.tools[0].cutting_data[0].feed_mm_min = 1270.0;
    inch.tools[0].flute_length_mm.reset();

    const QJsonObject bull_record = dataOf(mx::app::writeFusionLibrary({bull}, FusionContainer::Json)).at(0).toObject();
    QCOMPARE(bull_record.value("geometry").toObject().value("DC").toDouble(), 16.0);
    // The diameter's expression would override the new value in Fusion: it goes; the others stay.
    const QJsonObject expressions = bull_record.value("expressions").toObject();
    QVERIFY(!expressions.contains("tool_diameter"));
    QCOMPARE(expressions.value("tool_cornerRadius").toString(), QString("1 mm"));
    const QJsonObject brass = bull_record.value("start-values").toObject().value("presets").toArray().at(0).toObject();
    QCOMPARE(brass, (QJsonObject{{"name", "Brass"}, {"n", 8000}, {"f_z", 0.08}, {"stepdown", 2}}));

    const QJsonObject inch_record =
        dataOf(mx::app::writeFusionLibrary({inch.tools[0]}, FusionContainer::Json)).at(0).toObject();
    QCOMPARE(inch_record.value("unit").toString(), QString("inches"));
    QCOMPARE(inch_record.value("geometry").toObject().value("DC").toDouble(), 1.0);
    QVERIFY(!inch_record.value("geometry").toObject().contains("LCF"));  // removed in MillExpert
    const QJsonObject preset = inch_record.value("start-values").toObject().value("presets").toArray().at(0).toObject();
    QCOMPARE(preset.value("v_f").toDouble(), 50.0);                // 1270 mm/min in in/min
    QCOMPARE(preset.value("v_c").toDouble(), 392.69908169872417);  // unchanged: the file's own value
    QCOMPARE(preset.value("name").toString(), QString("6061"));
  }

  void aRenumberedToolKeepsItsRecord() {
    ImportedLibrary library = read("metric.json");
    library.tools[0].id = "T12";
    library.tools[2].id = "Finishing ball";
    const QJsonArray records = dataOf(mx::app::writeFusionLibrary(library.tools, FusionContainer::Json));
    QCOMPARE(records.at(0).toObject().value("post-process").toObject().value("number").toInt(), 12);
    QCOMPARE(records.at(0).toObject().value("post-process").toObject().value("length-offset").toInt(), 2);
    QCOMPARE(records.at(2).toObject().value("description").toString(), QString("Finishing ball"));
    const ImportedLibrary again =
        mx::app::readFusionLibrary(QJsonDocument(QJsonObject{{"data", records}}).toJson(), "x");
    QCOMPARE(again.tools[0].id, QString("T12"));
    QCOMPARE(again.tools[2].id, QString("Finishing ball"));
  }

  void aMillExpertToolTravelsWithItsDynamics() {
    ToolSpec tool;
    tool.id = "T12";
    tool.teeth = 4;
    tool.diameter_mm = 16.0;
    tool.helix_deg = 30.0;
    tool.modes_x = {{620.0, 3.5, 12.0, {}}, {1450.0, 2.0, 40.0, {}}};
    tool.modes_y = {{640.0, 3.0, 11.0, {}}};
    tool.Kt_N_mm2 = 2100.0;
    tool.Kr = 0.3;
    tool.max_force_N = 900.0;
    tool.pitch_deg = std::vector<double>{80.0, 100.0, 80.0, 100.0};
    tool.flute_length_mm = 32.0;

    const QByteArray json = mx::app::writeFusionLibrary({tool}, FusionContainer::Json);
    const QJsonObject record = dataOf(json).at(0).toObject();
    QCOMPARE(record.value("unit").toString(), QString("millimeters"));
    QCOMPARE(record.value("type").toString(), QString("flat end mill"));
    QCOMPARE(record.value("description").toString(), QString("T12"));
    QCOMPARE(record.value("post-process").toObject().value("number").toInt(), 12);
    QCOMPARE(record.value("geometry").toObject().value("HA").toDouble(), 30.0);
    QVERIFY(!record.value("guid").toString().isEmpty());
    QVERIFY(!QJsonDocument::fromJson(json).object().contains("version"));  // no guessed library version

    const ToolSpec back = mx::app::readFusionLibrary(json, "lib.json").tools.at(0);
    QCOMPARE(back.id, tool.id);
    QCOMPARE(back.teeth, 4);
    QCOMPARE(back.diameter_mm, 16.0);
    QCOMPARE(back.helix_deg, 30.0);
    QCOMPARE(back.modes_x, tool.modes_x);
    QCOMPARE(back.modes_y, tool.modes_y);
    QCOMPARE(back.Kt_N_mm2, tool.Kt_N_mm2);
    QCOMPARE(back.Kr, tool.Kr);
    QCOMPARE(back.max_force_N, tool.max_force_N);
    QCOMPARE(back.pitch_deg, tool.pitch_deg);
    QCOMPARE(back.flute_length_mm, std::optional(32.0));
    QCOMPARE(back.origin->format, QString("fusion"));
    QVERIFY(!back.origin->data.contains(mx::app::kFusionPayloadKey));  // consumed, not kept twice
    const QByteArray again = mx::app::writeFusionLibrary({back}, FusionContainer::Json);
    QCOMPARE(again, json);
    QCOMPARE(mx::app::readFusionLibrary(again, "lib.json").tools.at(0), back);
  }

  // The per-tool edge and axial coefficients travel in the millexpert key, in both containers, and an
  // imported Fusion tool keeps them through a second export.
  void edgeAndAxialOverridesTravelWithTheTool_data() {
    QTest::addColumn<FusionContainer>("container");
    QTest::newRow("JSON") << FusionContainer::Json;
    QTest::newRow(".tools") << FusionContainer::Zipped;
  }
  void edgeAndAxialOverridesTravelWithTheTool() {
    QFETCH(FusionContainer, container);
    ToolSpec tool;
    tool.id = "T5";
    tool.teeth = 3;
    tool.diameter_mm = 10.0;
    tool.Kt_N_mm2 = 1500.0;
    tool.Kte_N_mm = 18.5;
    tool.Kre_N_mm = 0.1 + 0.2;
    tool.Ka_N_mm2 = 1e5;
    tool.Kae_N_mm = 0.0;
    tool.modes_x = {{900.0, 2.0, 5.0, {}}};
    const QByteArray bytes = mx::app::writeFusionLibrary({tool}, container);
    const QByteArray json = mx::app::looksLikeZip(bytes) ? mx::app::readSingleJsonEntry(bytes) : bytes;
    const QJsonObject payload = dataOf(json).at(0).toObject().value(mx::app::kFusionPayloadKey).toObject();
    for (const char* key : {"Kte_N_mm", "Kre_N_mm", "Ka_N_mm2", "Kae_N_mm"}) QVERIFY2(payload.contains(key), key);
    const ToolSpec back = mx::app::readFusionLibrary(bytes, "lib.tools").tools.at(0);
    QCOMPARE(back.Kte_N_mm, tool.Kte_N_mm);
    QCOMPARE(back.Kre_N_mm, tool.Kre_N_mm);
    QCOMPARE(back.Ka_N_mm2, tool.Ka_N_mm2);
    QCOMPARE(back.Kae_N_mm, tool.Kae_N_mm);
    QCOMPARE(back.modes_x, tool.modes_x);
    QCOMPARE(mx::app::writeFusionLibrary({back}, container), bytes);

    // An imported Fusion tool (with its origin record) given the overrides keeps them too.
    ToolSpec imported = read("metric.json").tools.at(0);
    imported.Kte_N_mm = 7.0;
    imported.Kae_N_mm = 1e4;
    const ToolSpec again =
        mx::app::readFusionLibrary(mx::app::writeFusionLibrary({imported}, container), "lib.tools").tools.at(0);
    QCOMPARE(again, imported);
  }

  void aToolFromAnotherFormatIsANewRecord() {
    ToolSpec tool = read("metric.json").tools.at(1);
    tool.origin = mx::app::ToolOriginSpec{"linuxcnc", QJsonObject{{"T", 4}, {"comment", "bull nose"}}};
    const QJsonObject record = dataOf(mx::app::writeFusionLibrary({tool}, FusionContainer::Json)).at(0).toObject();
    QCOMPARE(record.value("unit").toString(), QString("millimeters"));
    QCOMPARE(record.value("type").toString(), QString("bull nose end mill"));
    QCOMPARE(record.value("post-process").toObject(), (QJsonObject{{"number", 4}}));
    QVERIFY(!record.contains("comment") && !record.contains("holder"));
    QCOMPARE(record.value("geometry").toObject(),
             (QJsonObject{{"DC", 12}, {"NOF", 4}, {"LCF", 26}, {"OAL", 83}, {"LB", 40}, {"RE", 1}, {"HA", 45}}));
  }

  void aFusionOriginWithoutUnitCannotBeExported() {
    ToolSpec tool = read("metric.json").tools.at(0);
    tool.origin->data.remove("unit");
    try {
      mx::app::writeFusionLibrary({tool}, FusionContainer::Json);
      QFAIL("exported");
    } catch (const ToolLibraryError& e) {
      QVERIFY2(QString(e.what()).startsWith("Fusion export of tool 'T2': its Fusion origin record has no usable unit"),
               e.what());
    }
  }

  void refusals_data() {
    QTest::addColumn<QByteArray>("library");
    QTest::addColumn<QString>("message");
    const auto row = [](const char* name, const QByteArray& library, const QString& message) {
      QTest::newRow(name) << library << message;
    };
    const QString tool = "tools.json: tool 'T7', ";
    row("diameter <= 0", oneTool(withKey(kGoodGeometry, "DC", -3)), tool + "geometry.DC: '-3' must be in (0, 1000] mm");
    row("diameter 0", oneTool(withKey(kGoodGeometry, "DC", 0)), tool + "geometry.DC: '0' must be in (0, 1000] mm");
    row("diameter missing", oneTool(withKey(kGoodGeometry, "DC", QJsonValue::Undefined)),
        tool + "geometry.DC: missing (required number in (0, 1000] mm)");
    row("diameter as text", oneTool(withKey(kGoodGeometry, "DC", "10 mm")),
        tool + "geometry.DC: '\"10 mm\"' must be a number");
    row("inch diameter over 1000 mm", oneTool(withKey(kGoodGeometry, "DC", 50), {{"unit", "inches"}}),
        tool + "geometry.DC: '50' in (1270 mm) must be in (0, 1000] mm");
    row("no flutes", oneTool(withKey(kGoodGeometry, "NOF", 0)),
        tool + "geometry.NOF: '0' must be an integer in [1, 100]");
    row("101 flutes", oneTool(withKey(kGoodGeometry, "NOF", 101)),
        tool + "geometry.NOF: '101' must be an integer in [1, 100]");
    row("2.5 flutes", oneTool(withKey(kGoodGeometry, "NOF", 2.5)),
        tool + "geometry.NOF: '2.5' must be an integer in [1, 100]");
    row("flutes missing", oneTool(withKey(kGoodGeometry, "NOF", QJsonValue::Undefined)),
        tool + "geometry.NOF: missing (required integer in [1, 100])");
    row("negative flute length", oneTool(withKey(kGoodGeometry, "LCF", -1)),
        tool + "geometry.LCF: '-1' must be in (0, 10000] mm");
    row("flute length over the overall length", oneTool(withKey(kGoodGeometry, "LCF", 80)),
        tool + "geometry.LCF: '80' must be <= geometry.OAL ('75')");
    row("body length over the overall length", oneTool(withKey(kGoodGeometry, "LB", 76)),
        tool + "geometry.LB: '76' must be <= geometry.OAL ('75')");
    row("corner radius over D/2", oneTool(withKey(kGoodGeometry, "RE", 6)),
        tool + "geometry.RE: '6' must be in [0, 5] mm");
    row("helix 90", oneTool(withKey(kGoodGeometry, "HA", 90)), tool + "geometry.HA: '90' must be in (-90, 90) deg");
    row("no geometry", oneTool({}, {{"geometry", "none"}}),
        tool + "geometry: missing or not an object (a milling cutter needs geometry.DC and geometry.NOF)");
    row("unit cm", oneTool(kGoodGeometry, {{"unit", "cm"}}),
        tool + "unit: '\"cm\"' must be \"millimeters\" or \"inches\"");
    row("unit missing", oneTool(kGoodGeometry, {{"unit", QJsonValue::Null}}),
        tool + "unit: missing (\"millimeters\" or \"inches\", in the tool, its expressions.tool_unit or the library)");
    row("units disagree", oneTool(kGoodGeometry, {{"expressions", QJsonObject{{"tool_unit", "'inches'"}}}}),
        tool + "unit: \"millimeters\" disagrees with expressions.tool_unit \"inches\"");
    row("tool number -1", oneTool(kGoodGeometry, {{"post-process", QJsonObject{{"number", -1}}}}),
        "tools.json: tool 'test cutter', post-process.number: '-1' must be an integer in [0, 1000000000]");
    row("tool number 2.5", oneTool(kGoodGeometry, {{"post-process", QJsonObject{{"number", 2.5}}}}),
        "tools.json: tool 'test cutter', post-process.number: '2.5' must be an integer in [0, 1000000000]");
    row("no name", oneTool(kGoodGeometry, {{"post-process", QJsonObject{}}, {"description", ""}}),
        "tools.json: tool '#1', description: missing (a tool without a post-process.number > 0 is named by its "
        "description or guid)");
    row("no type", oneTool(kGoodGeometry, {{"type", QJsonValue::Null}}),
        tool + "type: missing (a Fusion tool type such as \"flat end mill\")");
    row("payload not an object", oneTool(kGoodGeometry, {{"millexpert", 3}}),
        tool + "millexpert: must be an object (MillExpert's tool dynamics)");
    const QJsonObject bad_preset{{"name", "Steel"}, {"v_c", -1}};
    row("negative surface speed",
        oneTool(kGoodGeometry, {{"start-values", QJsonObject{{"presets", QJsonArray{bad_preset}}}}}),
        tool + "start-values.presets[0].v_c: '-1' must be in (0, 1e+05] m/min");
    const QJsonObject inch_preset{{"name", "Steel"}, {"f_z", 0.5}};
    row("inch chip load over 10 mm",
        oneTool(withKey(kGoodGeometry, "DC", 0.5),
                {{"unit", "inches"}, {"start-values", QJsonObject{{"presets", QJsonArray{inch_preset}}}}}),
        tool + "start-values.presets[0].f_z: '0.5' in (12.7 mm) must be in (0, 10] mm");
    row("preset name not text",
        oneTool(kGoodGeometry, {{"start-values", QJsonObject{{"presets", QJsonArray{QJsonObject{{"name", 3}}}}}}}),
        tool + "start-values.presets[0].name: must be a string");
    row("presets not a list", oneTool(kGoodGeometry, {{"start-values", QJsonObject{{"presets", "x"}}}}),
        tool + "start-values.presets: must be an array");
    row("entry not an object", R"({"data": [3]})", "tools.json: tool '#1', data[0]: must be an object (a tool)");
    row("no data", R"({"tools": []})",
        "tools.json, data: missing or not an array (a Fusion library is {\"data\": [tools]})");
    row("not an object", R"([1, 2])", "tools.json: not a Fusion tool library (an object with \"data\")");
    row("not JSON", "{\"data\": [", "tools.json: JSON syntax error at offset 10: unterminated array");
    row("bad library unit",
        R"({"data": [{"type": "flat end mill", "description": "x", "geometry": {"DC": 1, "NOF": 2}}],
                                "unit": "feet"})",
        "tools.json, unit: '\"feet\"' must be \"millimeters\" or \"inches\"");
  }
  void refusals() {
    QFETCH(QByteArray, library);
    QFETCH(QString, message);
    QCOMPARE(refusal(library), message);
  }

  void aBadPayloadNamesTheTool() {
    const QJsonObject payload{
        {"modes_x", QJsonArray{QJsonObject{{"freq_Hz", -5}, {"damping_pct", 3}, {"stiffness_N_per_um", 10}}}}};
    const QString message = refusal(oneTool(kGoodGeometry, {{"millexpert", payload}}));
    QVERIFY2(message.startsWith("tools.json: tool 'T7'"), qPrintable(message));
    QVERIFY2(message.contains("modes_x[0].freq_Hz"), qPrintable(message));
  }

  void oneBadToolRefusesTheLibrary() {
    QJsonArray data = dataOf(fileBytes("metric.json"));
    QJsonObject third = data.at(2).toObject();
    third.insert("geometry", withKey(third.value("geometry").toObject(), "RE", 4));
    data.replace(2, third);
    QCOMPARE(refusal(QJsonDocument(QJsonObject{{"data", data}}).toJson(), "metric.json"),
             QString("metric.json: tool '6 mm ball end mill', geometry.RE: '4' must be in [0, 3] mm"));
  }

  void badArchives_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("message");
    const QString prefix = ": not a readable Fusion .tools archive: ";
    QTest::newRow("truncated") << "truncated.tools"
                               << "truncated.tools" + prefix + "not a readable zip archive (libzip: Not a zip archive)";
    QTest::newRow("bomb") << "bomb.tools"
                          << "bomb.tools" + prefix +
                                 "entry 'tools.json' inflates to 68157452 bytes; at most 67108864 (64 MB) are read";
    QTest::newRow("understated size") << "understated_size.tools"
                                      << "understated_size.tools" + prefix +
                                             "entry 'tools.json' holds more than the 64 bytes its header declares";
    QTest::newRow("two libraries")
        << "two_libraries.tools"
        << "two_libraries.tools" + prefix +
               "the archive holds 2 .json entries ('a.json', 'b.json'); a tool library holds one";
    QTest::newRow("no library") << "no_json.tools"
                                << "no_json.tools" + prefix +
                                       "the archive holds no .json entry (entries: 'readme.txt')";
  }
  void badArchives() {
    QFETCH(QString, file);
    QFETCH(QString, message);
    QCOMPARE(refusal(fileBytes("bad/" + file), file), message);
  }

  void emptyArchiveIsRefused() {
    QCOMPARE(refusal(QByteArray("PK\x05\x06", 4) + QByteArray(18, '\0'), "empty.tools"),
             QString("empty.tools: not a readable Fusion .tools archive: the archive is empty"));
  }

  void zipWriterIsDeterministicAndReadable() {
    const QByteArray data = R"({"data": []})";
    const QByteArray zip = mx::app::writeSingleEntryZip("tools.json", data);
    QVERIFY(zip.startsWith("PK\x03\x04"));
    QCOMPARE(mx::app::writeSingleEntryZip("tools.json", data), zip);
    QCOMPARE(mx::app::readSingleJsonEntry(zip), data);
  }
};

MX_REGISTER_TEST(TestFusionLibrary)
#include "test_fusion_library.moc"
