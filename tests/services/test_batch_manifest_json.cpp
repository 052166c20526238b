// The batch manifest written back (app/services/batch_manifest_json.h): every field, written and read
// again (batchManifestFromJson), gives the same manifest; the optional lists are left out when absent,
// so the projects' own sections stay in effect.
#include "services/batch_manifest.h"
#include "services/batch_manifest_json.h"
#include "test_registry.h"

using mx::app::BatchManifest;

class TestBatchManifestJson : public QObject {
  Q_OBJECT

 private slots:
  void everyFieldRoundTrips() {
    BatchManifest m;
    m.computation = "lobes";
    m.folder = "/shop/studies";
    m.projects = {"cell-3.mxproj", "../library-alu.mxproj"};
    m.tools = QStringList{"T12", "T14"};
    m.machines = {QJsonObject{{"name", "DMU-50"}, {"spindle_power_W", 15000}, {"max_spindle_rpm", 18000}}};
    m.materials = {QJsonObject{{"name", "7075"}, {"Kt_N_mm2", 700}, {"Kr", 0.3}},
                   QJsonObject{{"name", "6061"}, {"Kt_N_mm2", 550}, {"Kr", 0.3}}};
    m.operations = {QJsonObject{{"milling", "down"}, {"radial_immersion", 0.5}, {"max_feed_per_tooth_mm", 0.15}}};
    m.options = QJsonObject{{"method", "zoa"}, {"from", 4000}, {"to", 18000}, {"step", 50}};
    const QJsonObject json = mx::app::batchManifestJson(m);
    QCOMPARE(json.keys(),
             (QStringList{"computation", "machines", "materials", "operations", "options", "projects", "tools"}));
    const BatchManifest back = mx::app::batchManifestFromJson(json, m.folder);
    QCOMPARE(back.computation, m.computation);
    QCOMPARE(back.projects, m.projects);
    QCOMPARE(back.tools, m.tools);
    QCOMPARE(back.machines, m.machines);
    QCOMPARE(back.materials, m.materials);
    QCOMPARE(back.operations, m.operations);
    QCOMPARE(back.options, m.options);
    QCOMPARE(back.projectPath(1), QString("/shop/library-alu.mxproj"));
  }

  void absentListsStayAbsent() {
    BatchManifest m;
    m.computation = "rank";
    m.folder = "/shop";
    m.projects = {"cell-3.mxproj"};
    const QJsonObject json = mx::app::batchManifestJson(m);
    QCOMPARE(json.keys(), (QStringList{"computation", "projects"}));
    const BatchManifest back = mx::app::batchManifestFromJson(json, m.folder);
    QVERIFY(!back.tools);
    QVERIFY(back.machines.empty() && back.materials.empty() && back.operations.empty());
    QVERIFY(back.options.isEmpty());
  }
};

MX_REGISTER_TEST(TestBatchManifestJson)
#include "test_batch_manifest_json.moc"
