// The materials library written back as JSON: the keys the CLI lists, only the optional values an entry
// has, and a library file that reads back to the same entries.
#include "services/material_library.h"
#include "services/material_library_json.h"
#include "test_registry.h"

using namespace mx::app;

class TestMaterialLibraryJson : public QObject {
  Q_OBJECT
 private slots:
  void entryKeys() {
    const std::vector<MaterialEntry> library = bundledMaterialLibrary();
    const QJsonObject al = materialEntryJson(materialById(library, "Al7075-T6"));
    QCOMPARE(al.keys(), QStringList({"Ka_N_mm2", "Kae_N_mm", "Kr", "Kre_N_mm", "Kt_N_mm2", "Kte_N_mm", "id",
                                     "iso_group", "kc11_N_mm2", "mc", "name", "sources"}));
    QCOMPARE(al.value("Kt_N_mm2").toDouble(), 767.01);
    QCOMPARE(al.value("sources").toObject().value("Kr").toObject().keys(), QStringList({"cite", "conditions", "url"}));
    const QJsonObject steel = materialEntryJson(materialById(library, "AISI1045"));
    QVERIFY(!steel.contains("Ka_N_mm2"));  // absent values are left out, never null
    QCOMPARE(steel.value("sources").toObject().value("Kr").toObject(),
             QJsonObject({{"note", "typical, source not checked"}}));
  }

  void libraryReadsBack() {
    const std::vector<MaterialEntry> library = bundledMaterialLibrary();
    const QByteArray written = materialLibraryJson(library);
    QCOMPARE(parseMaterialLibrary(written), library);
    QCOMPARE(materialEntriesJson(library).size(), qsizetype(library.size()));
  }
};

MX_REGISTER_TEST(TestMaterialLibraryJson)
#include "test_material_library_json.moc"
