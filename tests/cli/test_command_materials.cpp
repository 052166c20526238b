// millexpert-cli materials: the listing's keys, a shop's own library with --library, --apply copying an
// entry into the project's material section and nothing else, and exit 2 (with the project's bytes as
// they were) for a bad library file, an unknown id or bad flags.
#include <QFile>

#include "document/project.h"
#include "services/material_library.h"
#include "support/cli_runner.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx;

namespace {

using mx::test::kRubio;

QString copyOfRubio(const QTemporaryDir& dir) {
  QString path = dir.filePath("p.mxproj");
  QFile::copy(kRubio, path);
  QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
  return path;
}

const QByteArray kShopLibrary = R"({"format": "millexpert-materials", "version": 1, "materials": [
  {"id": "shop-steel", "name": "Shop steel", "iso_group": "P", "Kt_N_mm2": 2100, "Kr": 0.35,
   "process_damping_N_per_m": 2e5, "sources": {"Kt_N_mm2": {"cite": "own test cuts, 2024"}}}]})";

}  // namespace

class TestCommandMaterials : public QObject {
  Q_OBJECT
 private slots:
  void listsTheBundledLibrary() {
    const test::CliRun r = test::runCli({"materials"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.json.keys(), QStringList({"library", "materials"}));
    QCOMPARE(r.json.value("library").toString(), QString("bundled"));
    const QJsonArray materials = r.json.value("materials").toArray();
    QCOMPARE(materials.size(), 9);
    for (const auto& m : materials)
      for (const char* key : {"id", "name", "iso_group", "Kt_N_mm2", "Kr", "Kte_N_mm", "Kre_N_mm", "sources"})
        QVERIFY2(m.toObject().contains(key), key);
    const QJsonObject al = materials.at(1).toObject();
    QCOMPARE(al.value("id").toString(), QString("Al7075-T6"));
    QCOMPARE(al.value("Ka_N_mm2").toDouble(), 222.0);
    QVERIFY(al.value("sources").toObject().value("Kae_N_mm").toObject().value("cite").toString().contains("Table 5"));
  }

  void listsAnOwnLibrary() {
    QTemporaryDir dir;
    const QString library = test::writeText(dir, "shop.json", kShopLibrary);
    const test::CliRun r = test::runCli({"materials", "--library", library});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.json.value("library").toString(), library);
    const QJsonObject steel = r.json.value("materials").toArray().at(0).toObject();
    QCOMPARE(steel.value("process_damping_N_per_m").toDouble(), 2e5);
    QVERIFY(!steel.contains("Kte_N_mm"));
  }

  void applyCopiesTheEntry() {
    QTemporaryDir dir;
    const QString project = copyOfRubio(dir);
    const app::Project before = app::loadProject(project);
    const test::CliRun r = test::runCli({"materials", "--apply", "Al7075-T6", "--into", project});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.json.keys(), QStringList({"applied", "material", "project"}));
    QCOMPARE(r.json.value("material").toObject().value("library").toString(), QString("Al7075-T6"));
    const app::Project after = app::loadProject(project);
    QCOMPARE(after.material, app::materialSpecOf(app::materialById(app::bundledMaterialLibrary(), "Al7075-T6")));
    QCOMPARE(after.tools, before.tools);
    QCOMPARE(after.operation, before.operation);
    QCOMPARE(after.machine, before.machine);
  }

  void applyFromAnOwnLibrary() {
    QTemporaryDir dir;
    const QString project = copyOfRubio(dir);
    const QString library = test::writeText(dir, "shop.json", kShopLibrary);
    const test::CliRun r =
        test::runCli({"materials", "--library", library, "--apply", "shop-steel", "--into", project});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    const app::Project after = app::loadProject(project);
    QCOMPARE(*after.material->process_damping_N_per_m, 2e5);
    QCOMPARE(*after.material->library, QString("shop-steel"));
    QVERIFY(!after.material->Kte_N_mm);
  }

  // Exit 2, the reason on stderr, nothing on stdout, and the project's bytes as they were.
  void refusals_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QByteArray>("library");
    QTest::addColumn<QString>("message");
    const QByteArray badEdge = QByteArray(kShopLibrary).replace("\"Kr\": 0.35", "\"Kr\": 0.35, \"Kte_N_mm\": -2");
    QTest::newRow("bad library value") << QStringList{"--library", "LIB"} << badEdge
                                       << "shop.json: materials[0].Kte_N_mm = -2: must be in [0, 10000]";
    QTest::newRow("bad library on apply")
        << QStringList{"--library", "LIB", "--apply", "shop-steel", "--into", "PROJECT"} << badEdge
        << "materials[0].Kte_N_mm = -2: must be in [0, 10000]";
    QTest::newRow("library not JSON") << QStringList{"--library", "LIB"} << QByteArray("{")
                                      << "shop.json: invalid JSON";
    QTest::newRow("library missing") << QStringList{"--library", "MISSING"} << QByteArray()
                                     << "missing.json: cannot be read";
    QTest::newRow("unknown id") << QStringList{"--apply", "Al2024", "--into", "PROJECT"} << QByteArray()
                                << "material \"Al2024\" is not in the library (its ids: Al6061-T6,";
    QTest::newRow("apply without into") << QStringList{"--apply", "Al7075-T6"} << QByteArray()
                                        << "--apply needs --into PROJECT";
    QTest::newRow("a positional project")
        << QStringList{"PROJECT"} << QByteArray() << "materials takes no positional argument";
  }
  void refusals() {
    QFETCH(QStringList, arguments);
    QFETCH(QByteArray, library);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString project = copyOfRubio(dir);
    const QByteArray projectBytes = test::readBytes(project);
    for (QString& a : arguments) {
      if (a == "LIB") a = test::writeText(dir, "shop.json", library);
      if (a == "MISSING") a = dir.filePath("missing.json");
      if (a == "PROJECT") a = project;
    }
    const test::CliRun r = test::runCli(QStringList{"materials"} + arguments);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY(r.out.isEmpty());
    QCOMPARE(test::readBytes(project), projectBytes);
  }
};

MX_REGISTER_TEST(TestCommandMaterials)
#include "test_command_materials.moc"
