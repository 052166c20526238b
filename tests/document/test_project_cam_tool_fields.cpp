// The CAM fields of a tool (type, flute length, overall length, stickout, corner radius, cutting
// presets, origin; docs/project-file.md): they survive a save and a load exactly, keep their unknown
// keys, and every range is checked with a message that names the field, the value and the range.
#include <QJsonArray>
#include <QJsonDocument>

#include "document/project.h"
#include "test_registry.h"

using namespace mx::app;

namespace {

QJsonObject camTool() {
  return QJsonObject{
      {"id", "T7"},
      {"teeth", 3},
      {"diameter_mm", 12.7},
      {"helix_deg", 35},
      {"modes_x", QJsonArray{}},
      {"modes_y", QJsonArray{}},
      {"type", "bull nose end mill"},
      {"flute_length_mm", 25.4},
      {"overall_length_mm", 76.2},
      {"stickout_mm", 38.1},
      {"corner_radius_mm", 0.5},
      {"cutting_data", QJsonArray{QJsonObject{{"name", "Aluminium roughing"},
                                              {"speed_rpm", 12000},
                                              {"surface_speed_m_min", 478.8},
                                              {"feed_per_tooth_mm", 0.08},
                                              {"feed_mm_min", 2880},
                                              {"axial_depth_mm", 6},
                                              {"radial_depth_mm", 3},
                                              {"tool-coolant", "flood"}}}},
      {"origin", QJsonObject{{"format", "fusion"}, {"data", QJsonObject{{"guid", "abc"}, {"holder", QJsonObject{}}}}}},
  };
}

QJsonObject projectWith(const QJsonObject& tool) {
  return QJsonObject{{"format", "millexpert-project"}, {"version", 1}, {"name", "cam"}, {"tools", QJsonArray{tool}}};
}

QString camToolErrorOf(const QJsonObject& tool) {
  try {
    projectFromJson(projectWith(tool));
  } catch (const ProjectError& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

}  // namespace

class TestProjectCamToolFields : public QObject {
  Q_OBJECT

 private slots:
  void fieldsAreRead() {
    const Project p = projectFromJson(projectWith(camTool()));
    const ToolSpec& t = p.tools.at(0);
    QCOMPARE(t.type.value(), QString("bull nose end mill"));
    QCOMPARE(t.flute_length_mm.value(), 25.4);
    QCOMPARE(t.overall_length_mm.value(), 76.2);
    QCOMPARE(t.stickout_mm.value(), 38.1);
    QCOMPARE(t.corner_radius_mm.value(), 0.5);
    QCOMPARE(t.cutting_data.size(), std::size_t{1});
    const CuttingPresetSpec& preset = t.cutting_data[0];
    QCOMPARE(preset.name, QString("Aluminium roughing"));
    QCOMPARE(preset.speed_rpm.value(), 12000.0);
    QCOMPARE(preset.surface_speed_m_min.value(), 478.8);
    QCOMPARE(preset.feed_per_tooth_mm.value(), 0.08);
    QCOMPARE(preset.feed_mm_min.value(), 2880.0);
    QCOMPARE(preset.axial_depth_mm.value(), 6.0);
    QCOMPARE(preset.radial_depth_mm.value(), 3.0);
    QCOMPARE(preset.unknown.value("tool-coolant").toString(), QString("flood"));  // kept for the round trip
    QCOMPARE(t.origin->format, QString("fusion"));
    QCOMPARE(t.origin->data.value("guid").toString(), QString("abc"));
    QVERIFY(t.unknown.isEmpty());  // every CAM key is typed
  }

  void saveAndLoadAreExact() {
    const Project p = projectFromJson(projectWith(camTool()));
    const QJsonObject written = projectToJson(p);
    QCOMPARE(written.value("tools").toArray().at(0).toObject(), camTool());
    QCOMPARE(projectFromJson(written).tools, p.tools);
  }

  void toolJsonRoundTrip() {
    const ToolSpec t = projectFromJson(projectWith(camTool())).tools.at(0);
    QCOMPARE(toolFromJson(toolToJson(t), "tools[0]"), t);
  }

  // A tool without the CAM fields writes none of them (the files of earlier versions stay the same).
  void absentFieldsAreNotWritten() {
    QJsonObject plain = camTool();
    for (const char* key :
         {"type", "flute_length_mm", "overall_length_mm", "stickout_mm", "corner_radius_mm", "cutting_data", "origin"})
      plain.remove(key);
    const Project p = projectFromJson(projectWith(plain));
    QCOMPARE(projectToJson(p).value("tools").toArray().at(0).toObject(), plain);
  }

  void rangesAreChecked_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("message");
    QTest::newRow("type empty") << "type" << QJsonValue("  ")
                                << "tools[0].type = \"  \": must be a non-empty string of at most 100 characters";
    QTest::newRow("type 101 characters") << "type" << QJsonValue(QString(101, u'x'))
                                         << "(101 characters): must be a non-empty string of at most 100 characters";
    QTest::newRow("type number") << "type" << QJsonValue(3) << "tools[0].type: expected a string";
    QTest::newRow("flute length 0") << "flute_length_mm" << QJsonValue(0)
                                    << "tools[0].flute_length_mm = 0: must be in (0, 10000]";
    QTest::newRow("flute length > overall") << "flute_length_mm" << QJsonValue(80)
                                            << "tools[0].flute_length_mm = 80: must be in (0, 76.2] "
                                               "(tools[0].overall_length_mm = 76.2)";
    QTest::newRow("stickout > overall")
        << "stickout_mm" << QJsonValue(76.3)
        << "tools[0].stickout_mm = 76.3: must be in (0, 76.2] (tools[0].overall_length_mm = 76.2)";
    QTest::newRow("overall 1e4 + 1") << "overall_length_mm" << QJsonValue(10001)
                                     << "tools[0].overall_length_mm = 10001: must be in (0, 10000]";
    QTest::newRow("corner radius negative") << "corner_radius_mm" << QJsonValue(-0.1)
                                            << "tools[0].corner_radius_mm = -0.1: must be in [0, 6.35] "
                                               "(tools[0].diameter_mm = 12.7)";
    QTest::newRow("corner radius > D/2") << "corner_radius_mm" << QJsonValue(6.36)
                                         << "tools[0].corner_radius_mm = 6.36: must be in [0, 6.35]";
    QTest::newRow("origin format") << "origin" << QJsonValue(QJsonObject{{"format", "mastercam"}})
                                   << "tools[0].origin.format = \"mastercam\": must be \"fusion\", \"freecad\" or "
                                      "\"linuxcnc\"";
    QTest::newRow("origin without format")
        << "origin" << QJsonValue(QJsonObject{{"data", QJsonObject{}}}) << "tools[0].origin.format: missing";
    QTest::newRow("cutting data not array")
        << "cutting_data" << QJsonValue(QJsonObject{}) << "tools[0].cutting_data: expected an array";
  }
  void rangesAreChecked() {
    QFETCH(QString, key);
    QFETCH(QJsonValue, value);
    QFETCH(QString, message);
    QJsonObject tool = camTool();
    tool.insert(key, value);
    const QString error = camToolErrorOf(tool);
    QVERIFY2(error.contains(message), qPrintable(error));
  }

  void presetRangesAreChecked_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("message");
    QTest::newRow("name empty") << "name" << QJsonValue("")
                                << "tools[0].cutting_data[0].name = \"\": must be a non-empty";
    QTest::newRow("speed 0") << "speed_rpm" << QJsonValue(0)
                             << "tools[0].cutting_data[0].speed_rpm = 0: must be in (0, 1e+05]";
    QTest::newRow("speed 1e5 + 1") << "speed_rpm" << QJsonValue(100001)
                                   << "tools[0].cutting_data[0].speed_rpm = 100001: must be in (0, 1e+05]";
    QTest::newRow("surface speed -1") << "surface_speed_m_min" << QJsonValue(-1)
                                      << "tools[0].cutting_data[0].surface_speed_m_min = -1: must be in (0, 1e+05]";
    QTest::newRow("fz 10.5") << "feed_per_tooth_mm" << QJsonValue(10.5)
                             << "tools[0].cutting_data[0].feed_per_tooth_mm = 10.5: must be in (0, 10]";
    QTest::newRow("feed 0") << "feed_mm_min" << QJsonValue(0)
                            << "tools[0].cutting_data[0].feed_mm_min = 0: must be in (0, 1e+06]";
    QTest::newRow("ap 1001") << "axial_depth_mm" << QJsonValue(1001)
                             << "tools[0].cutting_data[0].axial_depth_mm = 1001: must be in (0, 1000]";
    QTest::newRow("ae string") << "radial_depth_mm" << QJsonValue("3")
                               << "tools[0].cutting_data[0].radial_depth_mm: expected a number";
  }
  void presetRangesAreChecked() {
    QFETCH(QString, key);
    QFETCH(QJsonValue, value);
    QFETCH(QString, message);
    QJsonObject tool = camTool();
    QJsonArray presets = tool.value("cutting_data").toArray();
    QJsonObject preset = presets.at(0).toObject();
    preset.insert(key, value);
    presets[0] = preset;
    tool.insert("cutting_data", presets);
    const QString error = camToolErrorOf(tool);
    QVERIFY2(error.startsWith(message), qPrintable(error));
  }

  void atMostOneHundredPresets() {
    QJsonObject tool = camTool();
    QJsonArray presets;
    for (int i = 0; i < 101; ++i) presets.append(QJsonObject{{"name", QString("p%1").arg(i)}});
    tool.insert("cutting_data", presets);
    QVERIFY2(camToolErrorOf(tool).startsWith("tools[0].cutting_data"), qPrintable(camToolErrorOf(tool)));
    presets.removeLast();
    tool.insert("cutting_data", presets);
    QCOMPARE(camToolErrorOf(tool), QString());
  }
};

MX_REGISTER_TEST(TestProjectCamToolFields)
#include "test_project_cam_tool_fields.moc"
