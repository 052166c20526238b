// The materials library: the bundled file loads and every entry passes the project rules, an entry's
// copy in a project survives the project file, a shop's own file is read with the other readers' size
// bound, and a bad library gives an error naming materials[i].field, the value and the range.
#include <QFile>

#include "document/project.h"
#include "document/project_validation.h"
#include "services/material_library.h"
#include "services/service_errors.h"
#include "support/error_message.h"
#include "support/hostile_files.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx::app;

namespace {

using mx::test::kRubio;

// A library of one entry: `fields` are added to (or replace) a valid aluminium entry, which then loses
// the key `without`.
QByteArray libraryWith(const QJsonObject& fields, const QString& without = {}) {
  QJsonObject entry{{"id", "A"}, {"name", "Aluminium"}, {"iso_group", "N"}, {"Kt_N_mm2", 700.0}, {"Kr", 0.3}};
  for (auto it = fields.begin(); it != fields.end(); ++it) entry.insert(it.key(), it.value());
  entry.remove(without);
  const QJsonObject root{{"format", "millexpert-materials"}, {"version", 1}, {"materials", QJsonArray{entry}}};
  return QJsonDocument(root).toJson();
}

// The InputError message of fn(), or a null string when nothing is thrown.
template <typename F>
QString materialErrorOf(F fn) {
  return mx::test::messageOf<InputError>(fn);
}

}  // namespace

class TestMaterialLibrary : public QObject {
  Q_OBJECT
 private slots:
  void bundledLibraryLoads() {
    const std::vector<MaterialEntry> library = bundledMaterialLibrary();
    QCOMPARE(library.size(), std::size_t{9});
    const MaterialEntry& al = materialById(library, "Al7075-T6");
    QCOMPARE(al.name, QString("Aluminium 7075-T6 (wrought, age hardened)"));
    QCOMPARE(al.iso_group, QString("N"));
    QCOMPARE(al.Kt_N_mm2, 767.01);
    QCOMPARE(al.Kr, 0.2201);
    QCOMPARE(*al.Kte_N_mm, 27.7);
    QCOMPARE(*al.Kre_N_mm, 26.6);
    QCOMPARE(*al.Ka_N_mm2, 222.0);
    QCOMPARE(*al.Kae_N_mm, 0.7);
    QVERIFY(!al.process_damping_N_per_m);  // none could be checked (docs/materials-sources.md)
    QCOMPARE(*al.kc11_N_mm2, 800.0);
    QCOMPARE(*al.mc, 0.25);
    QVERIFY(al.sources.value("Kt_N_mm2").cite->contains("doi:10.1186/s10033-021-00536-9"));
    QCOMPARE(*materialById(library, "AISI1045").sources.value("Kr").note, QString("typical, source not checked"));
    QVERIFY(!materialById(library, "AISI1045").Ka_N_mm2);
  }

  void everyBundledEntryValidates_data() {
    QTest::addColumn<QString>("id");
    for (const MaterialEntry& e : bundledMaterialLibrary()) QTest::newRow(qPrintable(e.id)) << e.id;
  }
  void everyBundledEntryValidates() {
    QFETCH(QString, id);
    const std::vector<MaterialEntry> library = bundledMaterialLibrary();
    const MaterialEntry& entry = materialById(library, id);
    Project project = loadProject(kRubio);
    project.material = materialSpecOf(entry);
    QCOMPARE(projectValidationError(project), QString());
    QCOMPARE(*project.material->library, id);
    QCOMPARE(project.material->name, entry.name);
    QCOMPARE(project.material->Kt_N_mm2, entry.Kt_N_mm2);
    QCOMPARE(project.material->Kte_N_mm, entry.Kte_N_mm);
    QCOMPARE(project.material->Kae_N_mm, entry.Kae_N_mm);
  }

  void entryRoundTripsThroughTheProjectFile() {
    QTemporaryDir dir;
    Project project = loadProject(kRubio);
    project.material = materialSpecOf(materialById(bundledMaterialLibrary(), "Al6082-T6"));
    const QString path = dir.filePath("p.mxproj");
    saveProject(project, path);
    const Project reread = loadProject(path);
    QCOMPARE(reread.material, project.material);
    QCOMPARE(*reread.material->library, QString("Al6082-T6"));
    QCOMPARE(*reread.material->Ka_N_mm2, 273.0);
  }

  void edgeValuesAreAccepted_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("value");
    QTest::newRow("Kt at its maximum") << "Kt_N_mm2" << 1e5;
    QTest::newRow("Kr zero") << "Kr" << 0.0;
    QTest::newRow("Kr at its maximum") << "Kr" << 10.0;
    QTest::newRow("Kte zero") << "Kte_N_mm" << 0.0;
    QTest::newRow("Kte at its maximum") << "Kte_N_mm" << 1e4;
    QTest::newRow("Kae at its maximum") << "Kae_N_mm" << 1e4;
    QTest::newRow("Ka at its maximum") << "Ka_N_mm2" << 1e5;
    QTest::newRow("process damping at its maximum") << "process_damping_N_per_m" << 1e9;
    QTest::newRow("mc zero") << "mc" << 0.0;
  }
  void edgeValuesAreAccepted() {
    QFETCH(QString, key);
    QFETCH(double, value);
    const std::vector<MaterialEntry> library = parseMaterialLibrary(libraryWith({{key, value}}));
    QCOMPARE(library.size(), std::size_t{1});
    Project project = loadProject(kRubio);
    project.material = materialSpecOf(library.front());
    QCOMPARE(projectValidationError(project), QString());
  }

  void badLibrariesGiveNamedErrors_data() {
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("message");
    QTest::newRow("negative edge force") << libraryWith({{"Kte_N_mm", -1.0}})
                                         << "materials[0].Kte_N_mm = -1: must be in [0, 10000]";
    QTest::newRow("edge force above 1e4")
        << libraryWith({{"Kre_N_mm", 10000.5}}) << "materials[0].Kre_N_mm = 10000.5: must be in [0, 10000]";
    QTest::newRow("axial edge force") << libraryWith({{"Kae_N_mm", -0.1}})
                                      << "materials[0].Kae_N_mm = -0.1: must be in [0, 10000]";
    QTest::newRow("axial coefficient") << libraryWith({{"Ka_N_mm2", 1.5e5}})
                                       << "materials[0].Ka_N_mm2 = 150000: must be in [0, 1e+05]";
    QTest::newRow("process damping") << libraryWith({{"process_damping_N_per_m", 2e9}})
                                     << "materials[0].process_damping_N_per_m = 2e+09: must be in [0, 1e+09]";
    QTest::newRow("Kt zero") << libraryWith({{"Kt_N_mm2", 0.0}}) << "materials[0].Kt_N_mm2 = 0: must be in (0, 1e+05]";
    QTest::newRow("Kr above 10") << libraryWith({{"Kr", 10.01}}) << "materials[0].Kr = 10.01: must be in [0, 10]";
    QTest::newRow("Kienzle exponent 1") << libraryWith({{"mc", 1.0}}) << "materials[0].mc = 1: must be in [0, 1)";
    QTest::newRow("Kt a string") << libraryWith({{"Kt_N_mm2", "700"}})
                                 << "materials[0].Kt_N_mm2: expected a number, got string";
    QTest::newRow("Kr missing") << libraryWith({}, "Kr") << "materials[0].Kr: missing (required number in [0, 10])";
    QTest::newRow("ISO group") << libraryWith({{"iso_group", "X"}})
                               << "materials[0].iso_group = \"X\": must be one of P, M, K, N, S, H (ISO 513)";
    QTest::newRow("empty name") << libraryWith({{"name", " "}})
                                << "materials[0].name = \" \": must be a non-empty string";
    QTest::newRow("source not an object") << libraryWith({{"sources", QJsonObject{{"Kr", "typical"}}}})
                                          << "materials[0].sources.Kr: expected an object, got string";
    QTest::newRow("source text not a string")
        << libraryWith({{"sources", QJsonObject{{"Kr", QJsonObject{{"note", 3}}}}}})
        << "materials[0].sources.Kr.note: expected a string, got number";
    QTest::newRow("duplicate id") << QByteArray(
                                         R"({"format": "millexpert-materials", "version": 1, "materials": [)"
                                         R"({"id": "A", "name": "A", "iso_group": "N", "Kt_N_mm2": 700, "Kr": 0.3},)"
                                         R"({"id": "A", "name": "B", "iso_group": "N", "Kt_N_mm2": 700, "Kr": 0.3}]})")
                                  << "materials[1].id = \"A\": must be unique (duplicate of materials[0].id)";
    QTest::newRow("entry not an object") << QByteArray(
                                                R"({"format": "millexpert-materials", "version": 1, "materials": [3]})")
                                         << "materials[0]: expected an object, got number";
    QTest::newRow("another format") << QByteArray(R"({"format": "millexpert-project", "version": 1, "materials": []})")
                                    << "format = \"millexpert-project\": must be \"millexpert-materials\"";
    QTest::newRow("a newer version") << QByteArray(
                                            R"({"format": "millexpert-materials", "version": 2, "materials": []})")
                                     << "version = 2: must be 1 (the version this build reads)";
    QTest::newRow("no materials") << QByteArray(R"({"format": "millexpert-materials", "version": 1})")
                                  << "materials: missing (required array of materials)";
    QTest::newRow("not JSON") << QByteArray("{\"format\": ") << "invalid JSON at offset";
    QTest::newRow("an array") << QByteArray("[]") << "the top level must be a JSON object, got an array";
  }
  void badLibrariesGiveNamedErrors() {
    QFETCH(QByteArray, bytes);
    QFETCH(QString, message);
    const QString error = materialErrorOf([&] { parseMaterialLibrary(bytes); });
    QVERIFY2(error.startsWith(message), qPrintable(error));
  }

  void ownLibraryFile() {
    QTemporaryDir dir;
    const QString path = mx::test::writeText(dir, "shop.json", libraryWith({{"id", "shop-steel"}}));
    QCOMPARE(readMaterialLibrary(path).front().id, QString("shop-steel"));
    const QString bad = mx::test::writeText(dir, "bad.json", libraryWith({{"Kte_N_mm", -1.0}}));
    QCOMPARE(materialErrorOf([&] { readMaterialLibrary(bad); }),
             bad + ": materials[0].Kte_N_mm = -1: must be in [0, 10000]");
  }

  void ownLibraryFileIsBounded_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("message");
    QTest::newRow("over 16 MB") << "bytes:" + QString::number(16 * mx::test::kMB + 1)
                                << "is over the 16 MB limit of a materials library";
    QTest::newRow("a FIFO") << "fifo"
                            << "a FIFO, not a regular file";
    QTest::newRow("a folder") << "folder"
                              << "a directory, not a regular file";
  }
  void ownLibraryFileIsBounded() {
    QFETCH(QString, kind);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString path = mx::test::hostileInput(dir, kind);
    QVERIFY(!path.isEmpty());
    const QString error = materialErrorOf([&] { readMaterialLibrary(path); });
    QVERIFY2(error.startsWith(path + ": ") && error.contains(message), qPrintable(error));
  }

  void unknownIdListsTheLibrary() {
    const QString error = materialErrorOf([] { materialById(bundledMaterialLibrary(), "Al2024"); });
    QVERIFY2(error.startsWith("material \"Al2024\" is not in the library (its ids: Al6061-T6, Al7075-T6,"),
             qPrintable(error));
  }
};

MX_REGISTER_TEST(TestMaterialLibrary)
#include "test_material_library.moc"
