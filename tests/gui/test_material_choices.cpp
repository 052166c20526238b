// The bundled materials library as the panel's picker gets it: one choice per entry, in the library's
// order, each the project's copy of its entry, with a tooltip saying how far each value's source goes.
#include "material_choices.h"
#include "test_registry.h"

using namespace mx;

class TestMaterialChoices : public QObject {
  Q_OBJECT
 private slots:
  void oneChoicePerEntry() {
    const std::vector<app::MaterialEntry> library = app::bundledMaterialLibrary();
    const QList<widgets::MaterialChoice> choices = gui::bundledMaterialChoices();
    QCOMPARE(choices.size(), qsizetype(library.size()));
    for (qsizetype i = 0; i < choices.size(); ++i) {
      QCOMPARE(choices[i].material, app::materialSpecOf(library[std::size_t(i)]));
      QCOMPARE(choices[i].iso_group, library[std::size_t(i)].iso_group);
    }
  }

  void tooltipsSayHowFarTheSourcesGo_data() {
    QTest::addColumn<QString>("id");
    QTest::addColumn<QStringList>("lines");
    QTest::newRow("measured in milling") << "Al7075-T6"
                                         << QStringList{"Al7075-T6, ISO group N",
                                                        "K_t 767.01 N/mm², K_r 0.2201, K_te 27.7 N/mm, K_re 26.6 N/mm, "
                                                        "K_a 222 N/mm², K_ae 0.7 N/mm",
                                                        "cited: K_t, K_r, K_te, K_re, K_a, K_ae",
                                                        "Sources: docs/materials-sources.md"};
    QTest::newRow("derived from Kienzle")
        << "AISI1045"
        << QStringList{"AISI1045, ISO group P", "K_t 1945 N/mm², K_r 0.35, K_te 48.4 N/mm, K_re 48 N/mm",
                       "derived: K_t, K_te", "typical, source not checked: K_r, K_re",
                       "Sources: docs/materials-sources.md"};
  }
  void tooltipsSayHowFarTheSourcesGo() {
    QFETCH(QString, id);
    QFETCH(QStringList, lines);
    for (const widgets::MaterialChoice& c : gui::bundledMaterialChoices())
      if (c.material.library == id) QCOMPARE(c.tooltip.split('\n'), lines);
  }
};

MX_REGISTER_TEST(TestMaterialChoices)
#include "test_material_choices.moc"
