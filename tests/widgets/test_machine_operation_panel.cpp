// The machine / operation / material / expert panel: shows the project, refuses invalid values in
// place with the reason (at once under the field), switches the radial engagement, creates missing
// sections, undoes; copies a materials-library entry in one undo step and says where the material
// came from.
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QSignalSpy>

#include "display_units.h"
#include "document/project_document.h"
#include "input_feedback.h"
#include "machine_operation_panel.h"
#include "support/project_files.h"
#include "test_registry.h"

using mx::app::Project;
using mx::widgets::MachineOperationPanel;

namespace {

using mx::test::kRubio;

// Two library entries as the GUI host hands them over; the second has every optional value.
QList<mx::widgets::MaterialChoice> twoChoices() {
  mx::app::MaterialSpec steel;
  steel.name = "Carbon steel AISI 1045";
  steel.Kt_N_mm2 = 1945.0;
  steel.Kr = 0.35;
  steel.Kte_N_mm = 48.4;
  steel.Kre_N_mm = 48.0;
  steel.library = "AISI1045";
  mx::app::MaterialSpec al;
  al.name = "Aluminium 7075-T6";
  al.Kt_N_mm2 = 767.01;
  al.Kr = 0.2201;
  al.Kte_N_mm = 27.7;
  al.Kre_N_mm = 26.6;
  al.Ka_N_mm2 = 222.0;
  al.Kae_N_mm = 0.7;
  al.process_damping_N_per_m = 2e5;
  al.library = "Al7075-T6";
  return {{"P", "steel", steel}, {"N", "aluminium", al}};
}

// The panel wired to a document as the main window wires it.
void wire(MachineOperationPanel& panel, mx::app::ProjectDocument& doc) {
  QObject::connect(&panel, &MachineOperationPanel::editRequested, &doc,
                   [&doc](const Project& edited, const QString& text) { doc.applyEdit(edited, text); });
  QObject::connect(&doc, &mx::app::ProjectDocument::changed, &panel, [&] { panel.setProject(doc.project()); });
  panel.setProject(doc.project());
}

// The form label of the row that holds the control of `path` (alone, or with its check box).
QString labelOf(const MachineOperationPanel& panel, const QString& path) {
  QWidget* control = panel.field(path);
  for (auto* form : panel.findChildren<QFormLayout*>()) {
    for (int row = 0; row < form->rowCount(); ++row) {
      QLayoutItem* field = form->itemAt(row, QFormLayout::FieldRole);
      QWidget* widget = field ? field->widget() : nullptr;
      if (widget && (widget == control || widget->isAncestorOf(control)))
        return qobject_cast<QLabel*>(form->itemAt(row, QFormLayout::LabelRole)->widget())->text();
    }
  }
  return {};
}

QString originText(const MachineOperationPanel& panel) {
  return qobject_cast<QLabel*>(panel.field("material.origin"))->text();
}

QDoubleSpinBox* spin(const MachineOperationPanel& panel, const QString& path) {
  return qobject_cast<QDoubleSpinBox*>(panel.field(path));
}

// The input note shown under `field`, "" when none is.
QString noteUnder(const QWidget* field) {
  const QLabel* note = mx::widgets::inputNote(field);
  if (!note || !note->isVisible()) return {};
  const QRect at(field->mapTo(field->window(), QPoint(0, 0)), field->size());
  return note->y() == at.bottom() + 1 ? note->text() : QString("(not under the field) ") + note->text();
}

void type(QDoubleSpinBox* box, const QString& text) {
  box->selectAll();
  QTest::keyClicks(box, text);
  QTest::keyClick(box, Qt::Key_Return);
}

}  // namespace

class TestMachineOperationPanel : public QObject {
  Q_OBJECT
 private slots:
  void showsTheProject() {
    MachineOperationPanel panel;
    panel.setProject(mx::app::loadProject(kRubio));
    QCOMPARE(spin(panel, "machine.spindle_power_W")->value(), 745.3);
    QCOMPARE(spin(panel, "machine.max_spindle_rpm")->value(), 12000.0);
    QVERIFY(qobject_cast<QCheckBox*>(panel.field("machine.max_spindle_rpm.enabled"))->isChecked());
    QVERIFY(!qobject_cast<QCheckBox*>(panel.field("machine.max_feed_mm_s.enabled"))->isChecked());
    QCOMPARE(spin(panel, "operation.radial_immersion")->value(), 1.0);
    QVERIFY(!spin(panel, "operation.radial_depth_mm")->isEnabled());
    QCOMPARE(spin(panel, "operation.max_feed_per_tooth_mm")->value(), 0.55);
    QCOMPARE(qobject_cast<QLineEdit*>(panel.field("material.name"))->text(), QString("Aluminium"));
    QCOMPARE(spin(panel, "material.Kt_N_mm2")->value(), 600.0);
    QCOMPARE(spin(panel, "expert.delta_per_s")->value(), 0.05);
    QCOMPARE(spin(panel, "expert.alpha")->value(), 0.95);
    for (const char* path : {"machine.spindle_power_W", "operation.milling", "operation.use_radial_depth",
                             "material.name", "material.Kr", "expert.alpha", "machine.max_feed_mm_s.enabled"})
      QVERIFY2(!panel.field(path)->toolTip().isEmpty(), path);
  }

  void invalidSpindlePowerIsRefused() {
    MachineOperationPanel panel;
    panel.setProject(mx::app::loadProject(kRubio));
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QSignalSpy spy(&panel, &MachineOperationPanel::editRequested);
    QDoubleSpinBox* power = spin(panel, "machine.spindle_power_W");
    type(power, "0");
    QCOMPARE(spy.count(), 0);
    QCOMPARE(power->value(), 745.3);  // the project's value is shown again
    QCOMPARE(panel.errorText(), QString("machine.spindle_power_W = 0: must be in (0, 1e+06]"));
    QVERIFY(power->toolTip().contains("Refused: machine.spindle_power_W = 0: must be in (0, 1e+06]"));
    QVERIFY(power->styleSheet().contains("border"));
    QCOMPARE(noteUnder(power),
             QString("machine.spindle_power_W = 0: must be in (0, 1e+06]. The field keeps its value."));

    type(power, "1500");  // a good value clears the mark
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).value<Project>().machine->spindle_power_W, 1500.0);
    QCOMPARE(panel.errorText(), QString());
    QVERIFY(power->styleSheet().isEmpty());
  }

  // What the box cannot take is answered as it is typed, named by the row's label and the unit.
  void badInputIsAnsweredAtTheField_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("message");
    QTest::newRow("negative power") << "machine.spindle_power_W"
                                    << "-5"
                                    << "Spindle power [W] must be between 0 and 1000000; \"-5\" is below the minimum.";
    QTest::newRow("letters in K_t") << "material.Kt_N_mm2"
                                    << "abc"
                                    << "Tangential force K_t [N/mm²] must be between 0 and 100000; \"abc\" is not a "
                                       "number.";
    QTest::newRow("alpha above 1") << "expert.alpha"
                                   << "2"
                                   << "Depth factor α must be between 0 and 1; \"2\" is above the maximum.";
  }
  void badInputIsAnsweredAtTheField() {
    QFETCH(QString, path);
    QFETCH(QString, typed);
    QFETCH(QString, message);
    MachineOperationPanel panel;
    panel.setProject(mx::app::loadProject(kRubio));
    panel.resize(500, 900);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QSignalSpy spy(&panel, &MachineOperationPanel::editRequested);
    QDoubleSpinBox* box = spin(panel, path);
    const double before = box->value();
    box->selectAll();
    QTest::keyClicks(box, typed);
    QCOMPARE(noteUnder(box), message);
    QTest::keyClick(box, Qt::Key_Return);
    QCOMPARE(spy.count(), 0);
    QCOMPARE(box->value(), before);
    QVERIFY(noteUnder(box).startsWith(message + " The value stays "));
  }

  void switchingToRadialDepth() {
    MachineOperationPanel panel;
    panel.setProject(mx::app::loadProject(kRubio));
    QSignalSpy spy(&panel, &MachineOperationPanel::editRequested);
    qobject_cast<QRadioButton*>(panel.field("operation.use_radial_depth"))->click();
    QCOMPARE(spy.count(), 1);
    const Project edited = spy.at(0).at(0).value<Project>();
    QVERIFY(!edited.operation->radial_immersion);
    QCOMPARE(*edited.operation->radial_depth_mm, 12.7);  // a/D = 1 of the smaller tool
    QCOMPARE(edited.operation->max_feed_per_tooth_mm, 0.55);
  }

  void radialDepthLargerThanAToolIsRefused() {
    Project p = mx::app::loadProject(kRubio);
    p.operation->radial_immersion.reset();
    p.operation->radial_depth_mm = 10.0;
    MachineOperationPanel panel;
    panel.setProject(p);
    QSignalSpy spy(&panel, &MachineOperationPanel::editRequested);
    type(spin(panel, "operation.radial_depth_mm"), "20");
    QCOMPARE(spy.count(), 0);
    QVERIFY2(panel.errorText().startsWith("operation.radial_depth_mm = 20: must be in (0, 12.7]"),
             qPrintable(panel.errorText()));
    QCOMPARE(spin(panel, "operation.radial_depth_mm")->value(), 10.0);
    // Back to a/D: 10 mm of the largest tool (30 mm).
    qobject_cast<QRadioButton*>(panel.field("operation.use_radial_immersion"))->click();
    QCOMPARE(spy.count(), 1);
    const Project edited = spy.at(0).at(0).value<Project>();
    QVERIFY(!edited.operation->radial_depth_mm);
    QCOMPARE(*edited.operation->radial_immersion, 10.0 / 30.0);
  }

  void optionalLimitsAndOtherFields() {
    MachineOperationPanel panel;
    panel.setProject(mx::app::loadProject(kRubio));
    QSignalSpy spy(&panel, &MachineOperationPanel::editRequested);
    qobject_cast<QCheckBox*>(panel.field("machine.max_spindle_rpm.enabled"))->setChecked(false);
    QVERIFY(!spy.at(0).at(0).value<Project>().machine->max_spindle_rpm);
    qobject_cast<QComboBox*>(panel.field("operation.milling"))->setCurrentIndex(1);
    QCOMPARE(spy.at(1).at(0).value<Project>().operation->milling, mx::MillingDirection::Down);
    type(spin(panel, "expert.alpha"), "0");
    QCOMPARE(spy.count(), 2);
    QCOMPARE(panel.errorText(), QString("expert.alpha = 0: must be in (0, 1]"));
    type(spin(panel, "material.Kr"), "0.25");
    QCOMPARE(spy.at(2).at(0).value<Project>().material->Kr, 0.25);
  }

  void missingSectionIsCreatedWithDefaults() {
    Project p = mx::app::loadProject(kRubio);
    p.machine.reset();
    p.expert.reset();
    MachineOperationPanel panel;
    panel.setProject(p);
    QCOMPARE(spin(panel, "machine.spindle_power_W")->value(), MachineOperationPanel::defaultMachine().spindle_power_W);
    QSignalSpy spy(&panel, &MachineOperationPanel::editRequested);
    type(spin(panel, "machine.spindle_power_W"), "2000");
    QCOMPARE(spy.count(), 1);
    const Project edited = spy.at(0).at(0).value<Project>();
    QVERIFY(edited.machine);
    QCOMPARE(edited.machine->spindle_power_W, 2000.0);
    QVERIFY(!edited.machine->max_spindle_rpm);
    QVERIFY(!edited.expert);  // only the edited section is created
  }

  void undoThroughTheDocument() {
    mx::app::ProjectDocument doc;
    doc.load(kRubio);
    MachineOperationPanel panel;
    QObject::connect(&panel, &MachineOperationPanel::editRequested, &doc,
                     [&doc](const Project& edited, const QString& text) { doc.applyEdit(edited, text); });
    QObject::connect(&doc, &mx::app::ProjectDocument::changed, &panel, [&] { panel.setProject(doc.project()); });
    panel.setProject(doc.project());
    type(spin(panel, "material.Kt_N_mm2"), "800");
    QCOMPARE(doc.project().material->Kt_N_mm2, 800.0);
    doc.undoStack()->undo();
    QCOMPARE(doc.project().material->Kt_N_mm2, 600.0);
    QCOMPARE(spin(panel, "material.Kt_N_mm2")->value(), 600.0);
  }

  void pickingALibraryEntryIsOneUndoStep() {
    mx::app::ProjectDocument doc;
    doc.load(kRubio);
    MachineOperationPanel panel;
    panel.setMaterialLibrary(twoChoices());
    wire(panel, doc);
    const mx::app::MaterialSpec before = *doc.project().material;
    QCOMPARE(originText(panel), QString("Not from the library (typed in)"));
    auto* picker = qobject_cast<QComboBox*>(panel.field("material.library"));
    QCOMPARE(picker->count(), 2);
    QCOMPARE(picker->itemText(1), QString("Aluminium 7075-T6 (ISO N)"));
    QCOMPARE(picker->itemData(1, Qt::ToolTipRole).toString(), QString("aluminium"));
    QCOMPARE(picker->currentIndex(), -1);
    QCOMPARE(picker->placeholderText(), QString("From library…"));

    const int steps = doc.undoStack()->index();
    emit picker->activated(1);
    QCOMPARE(doc.undoStack()->index(), steps + 1);
    QCOMPARE(*doc.project().material, twoChoices().at(1).material);  // every field and the library id
    QCOMPARE(doc.undoStack()->undoText(), QString("Material from the library: Aluminium 7075-T6"));
    QCOMPARE(spin(panel, "material.Kt_N_mm2")->value(), 767.01);
    QCOMPARE(spin(panel, "material.Ka_N_mm2")->value(), 222.0);
    QCOMPARE(spin(panel, "material.process_damping_N_per_m")->value(), 2e5);
    QVERIFY(qobject_cast<QCheckBox*>(panel.field("material.Kae_N_mm.enabled"))->isChecked());
    QCOMPARE(qobject_cast<QLineEdit*>(panel.field("material.name"))->text(), QString("Aluminium 7075-T6"));
    QCOMPARE(originText(panel), QString("From library entry Al7075-T6"));
    QCOMPARE(picker->currentIndex(), -1);

    doc.undoStack()->undo();
    QCOMPARE(*doc.project().material, before);
    QVERIFY(!qobject_cast<QCheckBox*>(panel.field("material.Kae_N_mm.enabled"))->isChecked());
    QCOMPARE(originText(panel), QString("Not from the library (typed in)"));
  }

  void editsSinceTheLibraryAreShown() {
    mx::app::ProjectDocument doc;
    doc.load(kRubio);
    MachineOperationPanel panel;
    panel.setMaterialLibrary(twoChoices());
    wire(panel, doc);
    emit qobject_cast<QComboBox*>(panel.field("material.library"))->activated(0);
    type(spin(panel, "material.Kt_N_mm2"), "2000");
    qobject_cast<QCheckBox*>(panel.field("material.Kre_N_mm.enabled"))->setChecked(false);
    QCOMPARE(*doc.project().material->library, QString("AISI1045"));  // the copy keeps its origin
    QCOMPARE(originText(panel), QString("From library entry AISI1045, edited since: K_t, K_re"));
    panel.setMaterialLibrary({});
    QCOMPARE(originText(panel), QString("From library entry AISI1045 (not in the loaded library)"));
    QVERIFY(!panel.field("material.library")->isEnabled());
  }

  // The optional coefficients: a check box each (unchecked = absent), labels with units, the project's
  // rules at the edges of their ranges, and a refusal naming the field, the value and the range.
  void optionalCoefficients_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("refusal");  // "" = accepted
    QTest::newRow("K_te negative") << "material.Kte_N_mm"
                                   << "-5"
                                   << "material.Kte_N_mm = -5: must be in [0, 10000]";
    QTest::newRow("K_te zero") << "material.Kte_N_mm"
                               << "0"
                               << "";
    QTest::newRow("K_te at 1e4") << "material.Kte_N_mm"
                                 << "10000"
                                 << "";
    QTest::newRow("K_re negative") << "material.Kre_N_mm"
                                   << "-0.01"
                                   << "material.Kre_N_mm = -0.01: must be in [0, 10000]";
    QTest::newRow("K_a at 1e5") << "material.Ka_N_mm2"
                                << "100000"
                                << "";
    QTest::newRow("K_a negative") << "material.Ka_N_mm2"
                                  << "-1"
                                  << "material.Ka_N_mm2 = -1: must be in [0, 1e+05]";
    QTest::newRow("K_ae") << "material.Kae_N_mm"
                          << "0.7"
                          << "";
    QTest::newRow("C_i at 1e9") << "material.process_damping_N_per_m"
                                << "1000000000"
                                << "";
    QTest::newRow("C_i negative") << "material.process_damping_N_per_m"
                                  << "-1"
                                  << "material.process_damping_N_per_m = -1: must be in [0, 1e+09]";
  }
  void optionalCoefficients() {
    QFETCH(QString, path);
    QFETCH(QString, typed);
    QFETCH(QString, refusal);
    Project p = mx::app::loadProject(kRubio);
    p.material->Kte_N_mm = p.material->Kre_N_mm = p.material->Ka_N_mm2 = p.material->Kae_N_mm = 10.0;
    p.material->process_damping_N_per_m = 10.0;
    MachineOperationPanel panel;
    panel.setProject(p);
    QSignalSpy spy(&panel, &MachineOperationPanel::editRequested);
    type(spin(panel, path), typed);
    if (refusal.isEmpty()) {
      QCOMPARE(spy.count(), 1);
      QCOMPARE(panel.errorText(), QString());
      return;
    }
    QCOMPARE(spy.count(), 0);
    QCOMPARE(panel.errorText(), refusal);
    QCOMPARE(spin(panel, path)->value(), 10.0);  // the project's value is shown again
    QVERIFY(spin(panel, path)->toolTip().contains("Refused: " + refusal));
  }

  void uncheckingACoefficientRemovesIt() {
    Project p = mx::app::loadProject(kRubio);
    p.material->Kte_N_mm = 31.5;
    MachineOperationPanel panel;
    panel.setProject(p);
    QSignalSpy spy(&panel, &MachineOperationPanel::editRequested);
    qobject_cast<QCheckBox*>(panel.field("material.Kte_N_mm.enabled"))->setChecked(false);
    QCOMPARE(spy.count(), 1);
    QVERIFY(!spy.at(0).at(0).value<Project>().material->Kte_N_mm);
    QVERIFY(!spin(panel, "material.Kte_N_mm")->isEnabled());
  }

  void everyMaterialLabelHasItsUnit() {
    MachineOperationPanel panel;
    const QHash<QString, QString> units{{"material.Kt_N_mm2", "[N/mm²]"},
                                        {"material.Kr", "[-]"},
                                        {"material.Kte_N_mm", "[N/mm]"},
                                        {"material.Kre_N_mm", "[N/mm]"},
                                        {"material.Ka_N_mm2", "[N/mm²]"},
                                        {"material.Kae_N_mm", "[N/mm]"},
                                        {"material.process_damping_N_per_m", "[N/m]"}};
    for (auto it = units.begin(); it != units.end(); ++it)
      QVERIFY2(labelOf(panel, it.key()).endsWith(it.value()), qPrintable(it.key() + ": " + labelOf(panel, it.key())));
  }

  void inchUnits() {
    mx::widgets::DisplayUnits units;
    units.setShop(mx::widgets::ShopUnits::inch());
    MachineOperationPanel panel;
    panel.setUnits(&units);
    panel.setProject(mx::app::loadProject(kRubio));
    QDoubleSpinBox* feed = spin(panel, "operation.max_feed_per_tooth_mm");
    QCOMPARE(feed->suffix(), QString(" in/tooth"));
    QCOMPARE(feed->value(), 0.02165);  // 0.55 mm
    QSignalSpy spy(&panel, &MachineOperationPanel::editRequested);
    type(feed, "0.01");
    QCOMPARE(spy.at(0).at(0).value<Project>().operation->max_feed_per_tooth_mm, 0.254);
  }
};

MX_REGISTER_TEST(TestMachineOperationPanel)
#include "test_machine_operation_panel.moc"
