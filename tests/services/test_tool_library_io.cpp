// What every tool-library format shares: the MillExpert data a tool carries through a foreign format
// (dynamicsPayload, withPayload), the side file, and messages that name the file, the tool and the field.
#include <QJsonArray>
#include <QJsonDocument>

#include "document/project.h"
#include "services/tool_formats/tool_library_io.h"
#include "support/error_message.h"
#include "test_registry.h"

using namespace mx::app;

namespace {

ToolSpec dynamicTool() {
  ToolSpec t;
  t.id = "T7";
  t.teeth = 4;
  t.diameter_mm = 16.0;
  t.helix_deg = 30.0;
  t.pitch_deg = std::vector<double>{80, 100, 80, 100};
  t.runout_um = std::vector<double>{0, 8, 0, -5};
  t.Kt_N_mm2 = 700.0;
  t.Kr = 0.3;
  t.radial_depth_mm = 4.0;
  t.max_force_N = 2500.0;
  t.modes_x = {{720.0, 2.5, 4.2, {}}, {1450.0, 1.2, 12.0, {}}};
  t.modes_y = {{735.0, 2.4, 4.4, {}}};
  t.type = "flat end mill";
  t.flute_length_mm = 32.0;
  return t;
}

// dynamicTool() overriding the material's edge and axial coefficients as well.
ToolSpec coefficientDynamicTool() {
  ToolSpec t = dynamicTool();
  t.Kte_N_mm = 24.5;
  t.Kre_N_mm = 0.1 + 0.2;
  t.Ka_N_mm2 = 1e5;
  t.Kae_N_mm = 0.0;
  return t;
}

// What a CAM format gives for the same tool: geometry, no dynamics.
ToolSpec mappedTool() {
  ToolSpec t;
  t.id = "T7";
  t.teeth = 4;
  t.diameter_mm = 16.0;
  t.type = "flat end mill";
  t.flute_length_mm = 32.0;
  return t;
}

// The ToolLibraryError message of fn(), or a null string when nothing is thrown.
template <typename F>
QString toolLibraryErrorOf(F fn) {
  return mx::test::messageOf<ToolLibraryError>(fn);
}

}  // namespace

class TestToolLibraryIo : public QObject {
  Q_OBJECT

 private slots:
  void payloadHoldsOnlyMillExpertData() {
    const QJsonObject payload = dynamicsPayload(dynamicTool());
    QCOMPARE(payload.keys(), QStringList({"Kr", "Kt_N_mm2", "helix_deg", "max_force_N", "modes_x", "modes_y",
                                          "pitch_deg", "radial_depth_mm", "runout_um"}));
    QCOMPARE(payload.value("modes_x").toArray().size(), 2);
  }

  // The edge and axial overrides are MillExpert's data: carried, and given back exactly.
  void payloadCarriesEdgeAndAxialOverrides() {
    const QJsonObject payload = dynamicsPayload(coefficientDynamicTool());
    QCOMPARE(payload.keys(),
             QStringList({"Ka_N_mm2", "Kae_N_mm", "Kr", "Kre_N_mm", "Kt_N_mm2", "Kte_N_mm", "helix_deg", "max_force_N",
                          "modes_x", "modes_y", "pitch_deg", "radial_depth_mm", "runout_um"}));
    QCOMPARE(payload.value("Kae_N_mm").toDouble(-1.0), 0.0);  // an override of 0 is carried, not dropped
    QCOMPARE(withPayload(mappedTool(), payload, "lib.tbl"), coefficientDynamicTool());
    // Through the side file (LinuxCNC) as well.
    const std::map<QString, QJsonObject> side =
        readSideFile(writeSideFile({coefficientDynamicTool()}), "tool.millexpert.json");
    QCOMPARE(withPayload(mappedTool(), side.at("T7"), "tool.tbl"), coefficientDynamicTool());
  }

  // The bounds are accepted from a payload: edge forces in [0, 1e4] N/mm, the axial coefficient in [0, 1e5].
  void payloadCoefficientBounds_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("message");  // "" = accepted
    for (const char* key : {"Kte_N_mm", "Kre_N_mm", "Kae_N_mm"}) {
      QTest::addRow("%s 0", key) << key << 0.0 << QString();
      QTest::addRow("%s 1e4", key) << key << 1e4 << QString();
      QTest::addRow("%s above 1e4", key)
          << key << 10000.5 << QString("tool.tbl: tool 'T7': %1 = 10000.5: must be in [0, 10000]").arg(key);
      QTest::addRow("%s negative", key) << key << -0.5
                                        << QString("tool.tbl: tool 'T7': %1 = -0.5: must be in [0, 10000]").arg(key);
    }
    QTest::newRow("Ka_N_mm2 0") << "Ka_N_mm2" << 0.0 << QString();
    QTest::newRow("Ka_N_mm2 1e5") << "Ka_N_mm2" << 1e5 << QString();
    QTest::newRow("Ka_N_mm2 above 1e5") << "Ka_N_mm2" << 100000.5
                                        << "tool.tbl: tool 'T7': Ka_N_mm2 = 100000.5: must be in [0, 1e+05]";
    QTest::newRow("Ka_N_mm2 negative") << "Ka_N_mm2" << -1.0
                                       << "tool.tbl: tool 'T7': Ka_N_mm2 = -1: must be in [0, 1e+05]";
  }
  void payloadCoefficientBounds() {
    QFETCH(QString, key);
    QFETCH(double, value);
    QFETCH(QString, message);
    ToolSpec back;
    const QString error = toolLibraryErrorOf([&] {
      back = withPayload(mappedTool(), QJsonObject{{key, value}}, "/shop/tool.tbl");
    });
    QCOMPARE(error, message);
    if (message.isEmpty()) QCOMPARE(toolToJson(back).value(key).toDouble(-1.0), value);
  }

  // The carried data and the format's geometry give back the whole tool.
  void payloadRestoresTheTool() {
    const ToolSpec back = withPayload(mappedTool(), dynamicsPayload(dynamicTool()), "lib.tbl");
    QCOMPARE(back, dynamicTool());
  }

  // The format's own geometry wins; a helix from the payload only when the format has none.
  void formatGeometryWins() {
    ToolSpec mapped = mappedTool();
    mapped.helix_deg = 45.0;
    mapped.type = "ball end mill";
    const ToolSpec back = withPayload(mapped, dynamicsPayload(dynamicTool()), "lib.tbl");
    QCOMPARE(back.helix_deg, 45.0);
    QCOMPARE(back.type.value(), QString("ball end mill"));
    QCOMPARE(back.modes_x, dynamicTool().modes_x);
  }

  void emptyPayloadKeepsTheToolRigid() {
    const ToolSpec back = withPayload(mappedTool(), {}, "lib.tbl");
    QCOMPARE(back, mappedTool());
    QVERIFY(back.modes_x.empty() && back.modes_y.empty());
  }

  void badPayloadNamesFileToolAndField_data() {
    QTest::addColumn<QJsonObject>("payload");
    QTest::addColumn<QString>("message");
    QTest::newRow("damping") << QJsonObject{{"modes_x",
                                             QJsonArray{QJsonObject{
                                                 {"freq_Hz", 700}, {"damping_pct", 150}, {"stiffness_N_per_um", 3}}}}}
                             << "tool.tbl: tool 'T7': modes_x[0].damping_pct = 150: must be in [0.001, 100)";
    QTest::newRow("pitch per tooth") << QJsonObject{{"pitch_deg", QJsonArray{180, 180}}}
                                     << "tool.tbl: tool 'T7': pitch_deg";
    QTest::newRow("wrong type") << QJsonObject{{"Kt_N_mm2", "hard"}}
                                << "tool.tbl: tool 'T7': Kt_N_mm2: expected a number";
    QTest::newRow("edge force type") << QJsonObject{{"Kte_N_mm", "high"}}
                                     << "tool.tbl: tool 'T7': Kte_N_mm: expected a number";
  }
  void badPayloadNamesFileToolAndField() {
    QFETCH(QJsonObject, payload);
    QFETCH(QString, message);
    const QString error = toolLibraryErrorOf([&] { withPayload(mappedTool(), payload, "/shop/tool.tbl"); });
    QVERIFY2(error.startsWith(message), qPrintable(error));
  }

  void sideFileCarriesEveryTool() {
    ToolSpec other = dynamicTool();
    other.id = "T8";
    other.modes_y.clear();
    const std::map<QString, QJsonObject> payloads =
        readSideFile(writeSideFile({dynamicTool(), other}), "tool.millexpert.json");
    QCOMPARE(payloads.size(), std::size_t{2});
    QCOMPARE(withPayload(mappedTool(), payloads.at("T7"), "tool.tbl"), dynamicTool());
    ToolSpec mapped8 = mappedTool();
    mapped8.id = "T8";
    QCOMPARE(withPayload(mapped8, payloads.at("T8"), "tool.tbl"), other);
  }

  void sideFilePathIsNamedAfterTheLibrary_data() {
    QTest::addColumn<QString>("library");
    QTest::addColumn<QString>("side");
    QTest::newRow("tool.tbl") << "/shop/mill/tool.tbl"
                              << "/shop/mill/tool.millexpert.json";
    QTest::newRow("two dots") << "/shop/mill/haas.v2.tbl"
                              << "/shop/mill/haas.v2.millexpert.json";
    QTest::newRow("relative") << "tool.tbl"
                              << "tool.millexpert.json";
  }
  void sideFilePathIsNamedAfterTheLibrary() {
    QFETCH(QString, library);
    QFETCH(QString, side);
    QCOMPARE(sideFilePath(library), side);
  }

  void badSideFileIsRefused_data() {
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("message");
    QTest::newRow("syntax") << QByteArray("{") << "t.millexpert.json: JSON syntax error at offset 1";
    QTest::newRow("format") << QByteArray(R"({"format": "other", "tools": []})")
                            << "t.millexpert.json, format: \"other\": must be \"millexpert-tool-dynamics\"";
    QTest::newRow("tools not array") << QByteArray(R"({"format": "millexpert-tool-dynamics", "tools": {}})")
                                     << "t.millexpert.json, tools: must be an array of tools";
    QTest::newRow("no id") << QByteArray(R"({"format": "millexpert-tool-dynamics", "tools": [{"Kr": 0.3}]})")
                           << "t.millexpert.json, tools[0].id: must be a non-empty string";
    QTest::newRow("repeated id")
        << QByteArray(R"({"format": "millexpert-tool-dynamics", "tools": [{"id": "T1"}, {"id": "T1"}]})")
        << "t.millexpert.json: tool 'T1', tools[1].id: repeats an earlier entry";
  }
  void badSideFileIsRefused() {
    QFETCH(QByteArray, bytes);
    QFETCH(QString, message);
    const QString error = toolLibraryErrorOf([&] { readSideFile(bytes, "t.millexpert.json"); });
    QVERIFY2(error.startsWith(message), qPrintable(error));
  }

  void errorTextNamesWhatItKnows() {
    QCOMPARE(toolLibraryError("/a/b/lib.json", "T1", "geometry.DC", "'-3' must be > 0"),
             QString("lib.json: tool 'T1', geometry.DC: '-3' must be > 0"));
    QCOMPARE(toolLibraryError("lib.json", {}, {}, "empty"), QString("lib.json: empty"));
    QCOMPARE(toolLibraryError("lib.json", {}, "data", "must be an array"), QString("lib.json, data: must be an array"));
  }

  void importedToolIsValidated() {
    ToolSpec t = mappedTool();
    t.teeth = 101;
    const QString error = toolLibraryErrorOf([&] { validateImportedTool(t, "lib.json"); });
    QCOMPARE(error, QString("lib.json: tool 'T7': teeth = 101: must be an integer in [1, 100]"));
  }
};

MX_REGISTER_TEST(TestToolLibraryIo)
#include "test_tool_library_io.moc"
