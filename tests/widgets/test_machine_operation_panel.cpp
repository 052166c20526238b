// The machine / operation / material / expert panel: shows the project, refuses invalid values in
// place with the reason, switches the radial engagement, creates missing sections, undoes.
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QRadioButton>
#include <QSignalSpy>

#include "display_units.h"
#include "document/project_document.h"
#include "machine_operation_panel.h"
#include "test_registry.h"

using mx::app::Project;
using mx::widgets::MachineOperationPanel;

namespace {

const char* kRubio = MX_PROJECTS_DIR "/rubio2006-tool-selection.mxproj";

QDoubleSpinBox* spin(const MachineOperationPanel& panel, const QString& path) {
  return qobject_cast<QDoubleSpinBox*>(panel.field(path));
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
    QSignalSpy spy(&panel, &MachineOperationPanel::editRequested);
    QDoubleSpinBox* power = spin(panel, "machine.spindle_power_W");
    type(power, "0");
    QCOMPARE(spy.count(), 0);
    QCOMPARE(power->value(), 745.3);  // the project's value is shown again
    QCOMPARE(panel.errorText(), QString("machine.spindle_power_W = 0: must be in (0, 1e+06]"));
    QVERIFY(power->toolTip().contains("Refused: machine.spindle_power_W = 0: must be in (0, 1e+06]"));
    QVERIFY(power->styleSheet().contains("border"));

    type(power, "1500");  // a good value clears the mark
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).value<Project>().machine->spindle_power_W, 1500.0);
    QCOMPARE(panel.errorText(), QString());
    QVERIFY(power->styleSheet().isEmpty());
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
