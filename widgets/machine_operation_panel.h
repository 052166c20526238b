#pragma once
// The machine / operation / material / expert-margin form of a project. Like the tool-library editor
// it shows the project given by setProject() and never changes it: an edit of one field builds the
// edited project, validates it (validateProject) and emits editRequested(), or refuses it in place
// (no signal, the field returns to the project's value, the reason appears in red under the field for a
// few seconds, under the form and in the field's tooltip, the field gets a red border). Input a field
// cannot take is answered under it as it is typed (checked_spin_box.h). A section the project lacks is shown
// with defaults and created by the first edit. Power, feed rate, lengths and chip load follow the shop
// units (DisplayUnits); the project stays in W, mm/s and mm. The material can be copied from the
// materials library given by setMaterialLibrary() in one edit; the panel says which entry the project's
// material came from and which of its values were edited since.
#include <QHash>
#include <QPointer>
#include <QWidget>
#include <functional>
#include <optional>

#include "display_units.h"
#include "document/project.h"
#include "material_choice.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QRadioButton;

namespace mx::widgets {

class MachineOperationPanel : public QWidget {
  Q_OBJECT
 public:
  explicit MachineOperationPanel(QWidget* parent = nullptr);

  void setProject(const app::Project& project);
  const app::Project& project() const { return project_; }
  void setUnits(DisplayUnits* units);  // spindle power, feed rate, radial depth and feed per tooth
  // The entries of the "From library…" picker, in the library's order.
  void setMaterialLibrary(const QList<MaterialChoice>& choices);

  // The control of a project field, by its path: "machine.spindle_power_W", "machine.max_spindle_rpm",
  // "machine.max_feed_mm_s", "operation.milling", "operation.radial_immersion",
  // "operation.radial_depth_mm", "operation.max_feed_per_tooth_mm", "material.name",
  // "material.Kt_N_mm2", "material.Kr", "material.Kte_N_mm", "material.Kre_N_mm", "material.Ka_N_mm2",
  // "material.Kae_N_mm", "material.process_damping_N_per_m", "expert.delta_per_s", "expert.alpha"; the check
  // boxes of the optional values are "<path>.enabled", the radio buttons of the radial choice
  // "operation.use_radial_immersion" and "operation.use_radial_depth", the library picker (a QComboBox)
  // "material.library" and the label naming the material's entry "material.origin". nullptr if unknown.
  QWidget* field(const QString& path) const { return controls_.value(path); }
  QString errorText() const { return error_; }  // the last refusal ("" after a good edit)

  // The sections the panel creates when the project lacks them.
  static app::MachineSpec defaultMachine();
  static app::MaterialSpec defaultMaterial();
  static app::OperationSpec defaultOperation();

 signals:
  void editRequested(const mx::app::Project& edited, const QString& description);

 private:
  // One numeric field: its spin box, an optional enabling check box, and access to the project.
  struct NumberField {
    QDoubleSpinBox* box = nullptr;
    QCheckBox* enabled = nullptr;                     // optional values only
    QString enabledTip = {};                          // the check box's tooltip, if not that of a limit
    std::optional<Quantity> quantity = std::nullopt;  // shown in its shop unit (the suffix is the unit)
    double to_base = 1.0;                             // the project's value times this is in base units
    QString suffix = {};
    double fallback = 0.0;  // shown while an optional value is absent
    // The range of the box, in project units. `min` may lie below the rule's range, so that a negative
    // value (a fit may give one) can be typed and is refused with the reason.
    double min = 0.0;
    double max = 0.0;
    std::function<std::optional<double>(const app::Project&)> get;
    std::function<void(app::Project&, std::optional<double>)> set;
  };
  // Creates the spin box (and check box) of `path`; returns the widget to put into the form.
  QWidget* addNumber(const QString& path, double max, int decimals, const QString& tip, NumberField field);
  QGroupBox* machineGroup();
  QGroupBox* operationGroup();
  QGroupBox* materialGroup();
  QWidget* materialPicker();
  // An optional coefficient of the material: unchecked means absent (0).
  QWidget* addCoefficient(const QString& path, double max, int decimals, const QString& tip,
                          std::optional<double> app::MaterialSpec::*member);
  QGroupBox* expertGroup();
  void commitNumber(const QString& path);
  void commitMilling();
  void commitName();
  void commitRadialChoice();
  void pickMaterial(int index);
  void showMaterialOrigin(const app::MaterialSpec& material);
  void request(const app::Project& edited, const QString& path, const QString& description);
  void markError(const QString& path, const QString& reason);
  void refresh();
  app::Project shown() const;  // project_ with default sections filled in
  // A project value of `f` as shown in its box, and back.
  double toDisplay(const NumberField& f, double value) const;
  double fromDisplay(const NumberField& f, double shown) const;

  app::Project project_;
  QPointer<DisplayUnits> units_;
  QHash<QString, QWidget*> controls_;
  QHash<QString, QString> tips_;
  QHash<QString, NumberField> numbers_;
  QHash<QString, QGroupBox*> groups_;
  QComboBox* milling_ = nullptr;
  QRadioButton* useImmersion_ = nullptr;
  QRadioButton* useDepth_ = nullptr;
  QLineEdit* materialName_ = nullptr;
  QComboBox* materialPicker_ = nullptr;
  QLabel* materialOrigin_ = nullptr;
  QList<MaterialChoice> materialChoices_;
  QLabel* errorLabel_ = nullptr;
  QString error_;
  QString errorPath_;
  bool updating_ = false;
};

}  // namespace mx::widgets
