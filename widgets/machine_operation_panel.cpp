#include "machine_operation_panel.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "checked_spin_box.h"
#include "document/project_validation.h"
#include "input_feedback.h"

namespace mx::widgets {

namespace {

using Opt = std::optional<double>;

app::MachineSpec& machine(app::Project& p) {
  if (!p.machine) p.machine = MachineOperationPanel::defaultMachine();
  return *p.machine;
}
app::MaterialSpec& material(app::Project& p) {
  if (!p.material) p.material = MachineOperationPanel::defaultMaterial();
  return *p.material;
}
app::OperationSpec& operation(app::Project& p) {
  if (!p.operation) p.operation = MachineOperationPanel::defaultOperation();
  return *p.operation;
}
app::ExpertSpec& expert(app::Project& p) {
  if (!p.expert) p.expert = app::ExpertSpec{};
  return *p.expert;
}

// The notes of a row's spin box name it as the row's label does (checked_spin_box.h).
void nameBoxesAfterLabels(const QFormLayout* form) {
  for (int row = 0; row < form->rowCount(); ++row) {
    const QLayoutItem* label = form->itemAt(row, QFormLayout::LabelRole);
    const QLayoutItem* field = form->itemAt(row, QFormLayout::FieldRole);
    if (!label || !field || !field->widget()) continue;
    auto* box = dynamic_cast<CheckedDoubleSpinBox*>(field->widget());
    if (!box) box = dynamic_cast<CheckedDoubleSpinBox*>(field->widget()->findChild<QDoubleSpinBox*>());
    QString name;
    if (const auto* text = qobject_cast<const QLabel*>(label->widget())) name = text->text();
    if (const auto* button = qobject_cast<const QAbstractButton*>(label->widget())) name = button->text();
    if (box) box->setFieldName(name.remove('&'));
  }
}

}  // namespace

app::MachineSpec MachineOperationPanel::defaultMachine() {
  app::MachineSpec m;
  m.spindle_power_W = 5000.0;
  return m;
}
app::MaterialSpec MachineOperationPanel::defaultMaterial() {
  app::MaterialSpec m;
  m.name = QStringLiteral("Aluminium");
  m.Kt_N_mm2 = 600.0;
  m.Kr = 0.3;
  return m;
}
app::OperationSpec MachineOperationPanel::defaultOperation() {
  return {MillingDirection::Up, 1.0, std::nullopt, 0.1};
}

MachineOperationPanel::MachineOperationPanel(QWidget* parent) : QWidget(parent) {
  errorLabel_ = new QLabel(this);
  errorLabel_->setStyleSheet("color: #c00000;");
  errorLabel_->setWordWrap(true);
  errorLabel_->setToolTip(tr("Why the last edit was refused; the project keeps its previous value"));
  errorLabel_->hide();
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(machineGroup());
  layout->addWidget(operationGroup());
  layout->addWidget(materialGroup());
  layout->addWidget(expertGroup());
  layout->addWidget(errorLabel_);
  layout->addStretch(1);
  for (const QGroupBox* group : std::as_const(groups_))
    nameBoxesAfterLabels(qobject_cast<QFormLayout*>(group->layout()));
  refresh();
}

QWidget* MachineOperationPanel::addNumber(const QString& path, double max, int decimals, const QString& tip,
                                          NumberField field) {
  field.box = new CheckedDoubleSpinBox(this);
  field.box->setRange(field.min, max);  // 0 (or below) can be typed and is refused with its reason where invalid
  field.max = max;
  field.box->setDecimals(decimals);
  field.box->setKeyboardTracking(false);
  field.box->setToolTip(tip);
  field.box->setObjectName(path);
  controls_.insert(path, field.box);
  tips_.insert(path, tip);
  connect(field.box, &QDoubleSpinBox::valueChanged, this, [this, path] { commitNumber(path); });
  QWidget* widget = field.box;
  if (field.enabled) {
    field.enabled->setToolTip(field.enabledTip.isEmpty()
                                  ? tr("Checked: limited to the value at the right; unchecked: no limit")
                                  : field.enabledTip);
    controls_.insert(path + ".enabled", field.enabled);
    connect(field.enabled, &QCheckBox::toggled, this, [this, path] { commitNumber(path); });
    widget = new QWidget(this);
    auto* row = new QHBoxLayout(widget);
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(field.enabled);
    row->addWidget(field.box, 1);
  }
  numbers_.insert(path, field);
  return widget;
}

QGroupBox* MachineOperationPanel::machineGroup() {
  auto* box = new QGroupBox(this);
  box->setToolTip(tr("The machine: spindle power and the optional speed and feed limits"));
  groups_.insert("machine", box);
  auto* form = new QFormLayout(box);
  form->addRow(tr("Spindle power"),
               addNumber("machine.spindle_power_W", 1e6, 1, tr("Spindle power P [W] (> 0)"),
                         {.quantity = Quantity::Power,
                          .get = [](const app::Project& p) { return Opt(p.machine->spindle_power_W); },
                          .set = [](app::Project& p, Opt v) { machine(p).spindle_power_W = v.value_or(0.0); }}));
  form->addRow(tr("Max spindle speed"),
               addNumber("machine.max_spindle_rpm", 1e5, 0, tr("Maximum spindle speed [rpm] (> 0); optional"),
                         {.enabled = new QCheckBox(this),
                          .suffix = " rpm",
                          .fallback = 12000.0,
                          .get = [](const app::Project& p) { return p.machine->max_spindle_rpm; },
                          .set = [](app::Project& p, Opt v) { machine(p).max_spindle_rpm = v; }}));
  form->addRow(tr("Max feed rate"), addNumber("machine.max_feed_mm_s", 1e5, 3, tr("Feed-drive limit (> 0); optional"),
                                              {.enabled = new QCheckBox(this),
                                               .quantity = Quantity::Feed,
                                               .to_base = 60.0,  // mm/s -> mm/min
                                               .fallback = 100.0,
                                               .get = [](const app::Project& p) { return p.machine->max_feed_mm_s; },
                                               .set = [](app::Project& p, Opt v) { machine(p).max_feed_mm_s = v; }}));
  return box;
}

QGroupBox* MachineOperationPanel::operationGroup() {
  auto* box = new QGroupBox(this);
  box->setToolTip(tr("The operation: milling direction, radial engagement and feed per tooth"));
  groups_.insert("operation", box);
  auto* form = new QFormLayout(box);
  milling_ = new QComboBox(this);
  milling_->addItems({tr("up milling"), tr("down milling")});
  milling_->setToolTip(tr("Up (conventional) or down (climb) milling"));
  controls_.insert("operation.milling", milling_);
  connect(milling_, &QComboBox::currentIndexChanged, this, &MachineOperationPanel::commitMilling);
  form->addRow(tr("Direction"), milling_);

  useImmersion_ = new QRadioButton(tr("Radial immersion a/D"), this);
  useImmersion_->setToolTip(tr("Give the radial engagement as the fraction a/D of each tool's diameter"));
  useDepth_ = new QRadioButton(tr("Radial depth a"), this);
  useDepth_->setToolTip(tr("Give the radial engagement as one radial depth a for every tool (a <= D)"));
  controls_.insert("operation.use_radial_immersion", useImmersion_);
  controls_.insert("operation.use_radial_depth", useDepth_);
  connect(useDepth_, &QRadioButton::toggled, this, &MachineOperationPanel::commitRadialChoice);
  form->addRow(useImmersion_, addNumber("operation.radial_immersion", 1.0, 3, tr("Radial immersion a/D in (0, 1]"),
                                        {.get = [](const app::Project& p) { return p.operation->radial_immersion; },
                                         .set = [](app::Project& p, Opt v) { operation(p).radial_immersion = v; }}));
  form->addRow(useDepth_,
               addNumber("operation.radial_depth_mm", 1e4, 4, tr("Radial depth of cut a in (0, D] for every tool"),
                         {.quantity = Quantity::Length,
                          .get = [](const app::Project& p) { return p.operation->radial_depth_mm; },
                          .set = [](app::Project& p, Opt v) { operation(p).radial_depth_mm = v; }}));
  form->addRow(tr("Max feed per tooth"),
               addNumber("operation.max_feed_per_tooth_mm", 10.0, 4, tr("Largest admissible feed per tooth (> 0)"),
                         {.quantity = Quantity::ChipLoad,
                          .get = [](const app::Project& p) { return Opt(p.operation->max_feed_per_tooth_mm); },
                          .set = [](app::Project& p, Opt v) { operation(p).max_feed_per_tooth_mm = v.value_or(0); }}));
  return box;
}

QGroupBox* MachineOperationPanel::materialGroup() {
  auto* box = new QGroupBox(this);
  box->setToolTip(tr("The work material's cutting-force coefficients (tools may override them)"));
  groups_.insert("material", box);
  auto* form = new QFormLayout(box);
  form->addRow(tr("Library"), materialPicker());
  materialName_ = new QLineEdit(this);
  materialName_->setToolTip(tr("Name of the work material"));
  controls_.insert("material.name", materialName_);
  connect(materialName_, &QLineEdit::editingFinished, this, &MachineOperationPanel::commitName);
  form->addRow(tr("Name"), materialName_);
  form->addRow(
      tr("Tangential force K_t [N/mm²]"),
      addNumber("material.Kt_N_mm2", 1e5, 2, tr("Specific tangential cutting force K_t = K_tc [N/mm²] in (0, 1e5]"),
                {.get = [](const app::Project& p) { return Opt(p.material->Kt_N_mm2); },
                 .set = [](app::Project& p, Opt v) { material(p).Kt_N_mm2 = v.value_or(0); }}));
  form->addRow(tr("Radial ratio K_r [-]"),
               addNumber("material.Kr", 10.0, 4, tr("Radial force ratio K_r = F_r / F_t = K_rc / K_tc in [0, 10]"),
                         {.get = [](const app::Project& p) { return Opt(p.material->Kr); },
                          .set = [](app::Project& p, Opt v) { material(p).Kr = v.value_or(0); }}));
  form->addRow(tr("Edge force K_te [N/mm]"),
               addCoefficient("material.Kte_N_mm", 1e4, 2,
                              tr("Tangential edge (ploughing) force per unit depth K_te [N/mm] in [0, 1e4]: static "
                                 "forces, torque and power, not the lobes"),
                              &app::MaterialSpec::Kte_N_mm));
  form->addRow(tr("Radial edge force K_re [N/mm]"),
               addCoefficient("material.Kre_N_mm", 1e4, 2,
                              tr("Radial edge (ploughing) force per unit depth K_re [N/mm] in [0, 1e4]"),
                              &app::MaterialSpec::Kre_N_mm));
  form->addRow(tr("Axial force K_a [N/mm²]"),
               addCoefficient("material.Ka_N_mm2", 1e5, 2,
                              tr("Axial cutting coefficient K_ac [N/mm²] in [0, 1e5]: the peak axial force"),
                              &app::MaterialSpec::Ka_N_mm2));
  form->addRow(
      tr("Axial edge force K_ae [N/mm]"),
      addCoefficient("material.Kae_N_mm", 1e4, 2, tr("Axial edge force per unit depth K_ae [N/mm] in [0, 1e4]"),
                     &app::MaterialSpec::Kae_N_mm));
  form->addRow(tr("Process damping C_i [N/m]"),
               addCoefficient("material.process_damping_N_per_m", 1e9, 0,
                              tr("Process-damping coefficient C_i [N/m] in [0, 1e9] (damping C_i b / V): raises the "
                                 "semi-discretization's lobes at low cutting speed; the ZOA leaves it out"),
                              &app::MaterialSpec::process_damping_N_per_m));
  return box;
}

QWidget* MachineOperationPanel::materialPicker() {
  materialPicker_ = new QComboBox(this);
  materialPicker_->setObjectName("material.library");
  materialPicker_->setPlaceholderText(tr("From library…"));
  // The entries' long names would set the dock's width; the list still shows them whole.
  materialPicker_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  materialPicker_->setMinimumContentsLength(16);
  materialPicker_->setToolTip(
      tr("Copy an entry of the materials library into the project's material (name and every coefficient; "
         "one undo step). The project keeps its own copy: edit it below."));
  controls_.insert("material.library", materialPicker_);
  connect(materialPicker_, &QComboBox::activated, this, &MachineOperationPanel::pickMaterial);
  materialOrigin_ = new QLabel(this);
  materialOrigin_->setObjectName("material.origin");
  materialOrigin_->setWordWrap(true);
  controls_.insert("material.origin", materialOrigin_);
  auto* widget = new QWidget(this);
  auto* column = new QVBoxLayout(widget);
  column->setContentsMargins(0, 0, 0, 0);
  column->addWidget(materialPicker_);
  column->addWidget(materialOrigin_);
  return widget;
}

QWidget* MachineOperationPanel::addCoefficient(const QString& path, double max, int decimals, const QString& tip,
                                               std::optional<double> app::MaterialSpec::*member) {
  return addNumber(path, max, decimals, tip,
                   {.enabled = new QCheckBox(this),
                    .enabledTip = tr("Checked: the value at the right; unchecked: absent, taken as 0"),
                    .min = -max,
                    .get = [member](const app::Project& p) { return (*p.material).*member; },
                    .set = [member](app::Project& p, Opt v) { material(p).*member = v; }});
}

QGroupBox* MachineOperationPanel::expertGroup() {
  auto* box = new QGroupBox(this);
  box->setToolTip(tr("The expert system's safety margins"));
  groups_.insert("expert", box);
  auto* form = new QFormLayout(box);
  form->addRow(tr("Margin δ"),
               addNumber("expert.delta_per_s", 1e4, 4,
                         tr("Rule 1.1 stability margin δ [1/s] (>= 0, below the smallest modal decay rate ζω_n)"),
                         {.suffix = " 1/s",
                          .get = [](const app::Project& p) { return Opt(p.expert->delta_per_s); },
                          .set = [](app::Project& p, Opt v) { expert(p).delta_per_s = v.value_or(0); }}));
  form->addRow(tr("Depth factor α"),
               addNumber("expert.alpha", 1.0, 3, tr("Rule 1.2 depth factor α in (0, 1]"),
                         {.get = [](const app::Project& p) { return Opt(p.expert->alpha); },
                          .set = [](app::Project& p, Opt v) { expert(p).alpha = v.value_or(0); }}));
  return box;
}

app::Project MachineOperationPanel::shown() const {
  app::Project p = project_;
  machine(p);
  material(p);
  operation(p);
  expert(p);
  return p;
}

void MachineOperationPanel::setProject(const app::Project& project) {
  project_ = project;
  refresh();
}

void MachineOperationPanel::setUnits(DisplayUnits* units) {
  followUnits(this, units_, units, &MachineOperationPanel::refresh);
}

void MachineOperationPanel::setMaterialLibrary(const QList<MaterialChoice>& choices) {
  materialChoices_ = choices;
  materialPicker_->clear();
  for (int i = 0; i < choices.size(); ++i) {
    const MaterialChoice& c = choices[i];
    materialPicker_->addItem(tr("%1 (ISO %2)").arg(c.material.name, c.iso_group));
    materialPicker_->setItemData(i, c.tooltip, Qt::ToolTipRole);
  }
  materialPicker_->setEnabled(!choices.isEmpty());
  refresh();
}

double MachineOperationPanel::toDisplay(const NumberField& f, double value) const {
  return f.quantity ? DisplayUnits::of(units_).fromBase(*f.quantity, value * f.to_base) : value;
}

double MachineOperationPanel::fromDisplay(const NumberField& f, double shown) const {
  return f.quantity ? DisplayUnits::of(units_).toBase(*f.quantity, shown) / f.to_base : shown;
}

void MachineOperationPanel::refresh() {
  updating_ = true;
  const app::Project s = shown();
  const ShopUnits& units = DisplayUnits::of(units_);
  for (auto it = numbers_.begin(); it != numbers_.end(); ++it) {
    NumberField& f = it.value();
    const Opt v = f.get(s);
    if (f.quantity) {
      f.box->setSuffix(" " + units.symbol(*f.quantity));
      f.box->setDecimals(units.decimals(*f.quantity));
      f.box->setRange(toDisplay(f, f.min), toDisplay(f, f.max));
    } else {
      f.box->setSuffix(f.suffix);
    }
    if (f.enabled) f.enabled->setChecked(v.has_value());
    f.box->setEnabled(v.has_value());
    f.box->setValue(toDisplay(f, v.value_or(f.fallback)));
  }
  milling_->setCurrentIndex(s.operation->milling == MillingDirection::Up ? 0 : 1);
  useDepth_->setChecked(s.operation->radial_depth_mm.has_value());
  useImmersion_->setChecked(!s.operation->radial_depth_mm.has_value());
  materialName_->setText(s.material->name);
  materialName_->setCursorPosition(0);   // a library name is long: its start says what it is
  materialPicker_->setCurrentIndex(-1);  // the placeholder: the picker is an action, not a state
  showMaterialOrigin(*s.material);
  const QString absent = tr(" (not in the project: defaults shown, an edit adds it)");
  groups_["machine"]->setTitle(tr("Machine") + (project_.machine ? QString() : absent));
  groups_["operation"]->setTitle(tr("Operation") + (project_.operation ? QString() : absent));
  groups_["material"]->setTitle(tr("Material") + (project_.material ? QString() : absent));
  groups_["expert"]->setTitle(tr("Expert margins") + (project_.expert ? QString() : absent));
  updating_ = false;
}

void MachineOperationPanel::commitNumber(const QString& path) {
  if (updating_) return;
  const NumberField& f = numbers_[path];
  if (f.enabled) f.box->setEnabled(f.enabled->isChecked());
  const Opt current = f.get(shown());
  Opt wanted;
  if (!f.enabled || f.enabled->isChecked()) wanted = fromDisplay(f, f.box->value());
  if (current.has_value() == wanted.has_value()) {
    // Unchanged as shown (the box rounds to its decimals): keep the project's exact value.
    if (!wanted) return;
    const double shownValue = toDisplay(f, *current);
    if (std::abs(shownValue - f.box->value()) <= 0.5 * std::pow(10.0, -f.box->decimals())) return;
  }
  app::Project edited = project_;
  f.set(edited, wanted);
  request(edited, path, wanted ? tr("Set %1").arg(path) : tr("Remove %1").arg(path));
}

void MachineOperationPanel::commitMilling() {
  if (updating_) return;
  const MillingDirection wanted = milling_->currentIndex() == 0 ? MillingDirection::Up : MillingDirection::Down;
  if (shown().operation->milling == wanted && project_.operation) return;
  app::Project edited = project_;
  operation(edited).milling = wanted;
  request(edited, "operation.milling", wanted == MillingDirection::Up ? tr("Up milling") : tr("Down milling"));
}

void MachineOperationPanel::commitName() {
  if (updating_ || (project_.material && materialName_->text() == project_.material->name)) return;
  app::Project edited = project_;
  material(edited).name = materialName_->text();
  request(edited, "material.name", tr("Rename the material"));
}

// Switching keeps the engagement of the smallest tool: a = a/D * D_min, or a/D = a / D_max (<= 1).
void MachineOperationPanel::commitRadialChoice() {
  if (updating_) return;
  app::Project edited = project_;
  app::OperationSpec& op = operation(edited);
  double dMin = 0.0, dMax = 0.0;
  for (const app::ToolSpec& t : edited.tools) {
    dMin = dMin == 0.0 ? t.diameter_mm : std::min(dMin, t.diameter_mm);
    dMax = std::max(dMax, t.diameter_mm);
  }
  if (useDepth_->isChecked()) {
    if (op.radial_depth_mm) return;
    op.radial_depth_mm = op.radial_immersion.value_or(1.0) * (dMin > 0.0 ? dMin : 10.0);
    op.radial_immersion.reset();
    request(edited, "operation.radial_depth_mm", tr("Give the radial depth of cut"));
  } else {
    if (op.radial_immersion) return;
    const double depth = op.radial_depth_mm.value_or(1.0);
    op.radial_immersion = dMax > 0.0 ? std::min(1.0, depth / dMax) : 1.0;
    op.radial_depth_mm.reset();
    request(edited, "operation.radial_immersion", tr("Give the radial immersion"));
  }
}

void MachineOperationPanel::pickMaterial(int index) {
  if (updating_ || index < 0 || index >= materialChoices_.size()) return;
  app::Project edited = project_;
  edited.material = materialChoices_[index].material;
  request(edited, "material.library", tr("Material from the library: %1").arg(edited.material->name));
  materialPicker_->setCurrentIndex(-1);
}

void MachineOperationPanel::showMaterialOrigin(const app::MaterialSpec& material) {
  if (!material.library) {
    materialOrigin_->setText(tr("Not from the library (typed in)"));
    return;
  }
  const QString& id = *material.library;
  const auto entry = std::find_if(materialChoices_.begin(), materialChoices_.end(),
                                  [&id](const MaterialChoice& c) { return c.material.library == id; });
  if (entry == materialChoices_.end()) {
    materialOrigin_->setText(tr("From library entry %1 (not in the loaded library)").arg(id));
    return;
  }
  const QStringList edited = editedMaterialFields(material, entry->material);
  materialOrigin_->setText(edited.isEmpty() ? tr("From library entry %1").arg(id)
                                            : tr("From library entry %1, edited since: %2").arg(id, edited.join(", ")));
}

void MachineOperationPanel::request(const app::Project& edited, const QString& path, const QString& description) {
  const QString error = app::projectValidationError(edited);
  markError(error.isEmpty() ? QString() : path, error);
  if (!error.isEmpty()) {
    refresh();  // refused in place: the field shows the project's value again
    return;
  }
  emit editRequested(edited, description);
}

void MachineOperationPanel::markError(const QString& path, const QString& reason) {
  if (QWidget* old = controls_.value(errorPath_)) {
    old->setStyleSheet({});
    old->setToolTip(tips_.value(errorPath_, old->toolTip()));
  }
  if (QWidget* w = controls_.value(path)) {
    if (!tips_.contains(path)) tips_.insert(path, w->toolTip());
    w->setStyleSheet("border: 1px solid #c00000;");
    w->setToolTip(tips_.value(path) + "\n" + tr("Refused: %1").arg(reason));
  }
  errorPath_ = path;
  error_ = reason;
  errorLabel_->setText(reason.isEmpty() ? QString() : tr("Refused: %1").arg(reason));
  errorLabel_->setVisible(!reason.isEmpty());
  // The label is at the bottom of a scrolling panel: the field says it at once.
  if (!reason.isEmpty()) showInputNote(controls_.value(path, this), tr("%1. The field keeps its value.").arg(reason));
}

}  // namespace mx::widgets
