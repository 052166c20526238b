#include "tool_table_model.h"

#include <cmath>

#include "document/project_rules.h"
#include "document/project_validation.h"
#include "document/tooth_list_text.h"
#include "range_delegate.h"

namespace mx::widgets {

namespace {

QString number(double value) {
  return QString::number(value, 'g', 6);
}

const char* fieldName(int column) {
  static const char* kNames[] = {
      "id",       "teeth",    "diameter_mm", "helix_deg", "pitch_deg",       "runout_um",   "Kt_N_mm2", "Kr",
      "Kte_N_mm", "Kre_N_mm", "Ka_N_mm2",    "Kae_N_mm",  "radial_depth_mm", "max_force_N", "modes_x",  "modes_y"};
  return kNames[column];
}

}  // namespace

ToolTableModel::ToolTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void ToolTableModel::setProject(const app::Project& project) {
  if (project.tools.size() == project_.tools.size()) {
    project_ = project;
    refreshAll();
    return;
  }
  beginResetModel();
  project_ = project;
  endResetModel();
}

void ToolTableModel::setUnits(DisplayUnits* units) {
  followUnits(this, units_, units, &ToolTableModel::refreshAll);
}

void ToolTableModel::refreshAll() {
  emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
  if (rowCount() > 0) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

int ToolTableModel::rowOf(const QString& id) const {
  for (std::size_t i = 0; i < project_.tools.size(); ++i) {
    if (project_.tools[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

QString ToolTableModel::idAt(int row) const {
  return row >= 0 && row < rowCount() ? project_.tools[std::size_t(row)].id : QString();
}

int ToolTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(project_.tools.size());
}

int ToolTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant ToolTableModel::editValue(const app::ToolSpec& t, int column) const {
  const auto opt = [](const std::optional<double>& v) { return v ? QVariant(*v) : QVariant(); };
  switch (column) {
    case Id:
      return t.id;
    case Teeth:
      return t.teeth;
    case Diameter:
      return toDisplay(t.diameter_mm);
    case Helix:
      return t.helix_deg;
    case Pitch:
      return t.pitch_deg ? app::toothListText(*t.pitch_deg, "; ") : uniformPitchText();
    case Runout:
      return t.runout_um ? app::toothListText(*t.runout_um, "; ") : noRunoutText();
    case Kt:
      return opt(t.Kt_N_mm2);
    case Kr:
      return opt(t.Kr);
    case Kte:
      return opt(t.Kte_N_mm);
    case Kre:
      return opt(t.Kre_N_mm);
    case Ka:
      return opt(t.Ka_N_mm2);
    case Kae:
      return opt(t.Kae_N_mm);
    case RadialDepth:
      return t.radial_depth_mm ? QVariant(toDisplay(*t.radial_depth_mm)) : QVariant();
    case MaxForce:
      return t.max_force_N ? QVariant(DisplayUnits::of(units_).fromBase(Quantity::Force, *t.max_force_N)) : QVariant();
    case ModesX:
      return static_cast<int>(t.modes_x.size());
    case ModesY:
      return static_cast<int>(t.modes_y.size());
    default:
      return {};
  }
}

// The spin-box ranges (RangeDelegate roles), in display units. The minimum of a required positive
// value is 0 so that typing 0 is possible and refused with its reason; a closed lower bound (teeth)
// is the box's own.
QVariant ToolTableModel::rangeData(int column, int role) const {
  using D = RangeDelegate;
  const bool inch = units_ && units_->length() == DisplayUnits::Length::Inch;
  const int lengthDecimals = units_ ? units_->lengthDecimals() : 4;
  struct Range {
    double lo, hi;
    int decimals;
    double step;
    const char* special;
  };
  Range r{};
  switch (column) {
    case Teeth:
      r = {app::rules::kTeeth.lo, app::rules::kTeeth.hi, 0, 1, ""};
      break;
    case Diameter:
      r = {0, inch ? 40.0 : 1000.0, lengthDecimals, inch ? 0.01 : 0.1, ""};
      break;
    case Helix:
      r = {-90, 90, 2, 1, ""};
      break;
    case Kt:
      r = {0, 100000, 2, 10, "material's"};
      break;
    case Kr:
      r = {-0.001, 10, 3, 0.01, "material's"};
      break;
    case Kte:
    case Kre:
    case Kae:  // 0 is a value: the special text "material's" sits just below
      r = {-0.01, app::rules::kEdgeForceNmm.hi, 2, 1, "material's"};
      break;
    case Ka:
      r = {-0.01, app::rules::kAxialPressureNmm2.hi, 2, 10, "material's"};
      break;
    case RadialDepth:
      r = {0, inch ? 40.0 : 1000.0, lengthDecimals, inch ? 0.01 : 0.1, "operation's"};
      break;
    case MaxForce:
      r = {0, DisplayUnits::of(units_).fromBase(Quantity::Force, 1e7), 0, 100, "none"};
      break;
    default:
      return {};
  }
  switch (role) {
    case D::MinimumRole:
      return r.lo;
    case D::MaximumRole:
      return r.hi;
    case D::DecimalsRole:
      return r.decimals;
    case D::StepRole:
      return r.step;
    case D::SpecialTextRole:
      return QString(r.special);
    case D::SuffixRole:
      if (column == MaxForce) return " " + DisplayUnits::of(units_).symbol(Quantity::Force);
      return column == Diameter || column == RadialDepth ? " " + lengthUnit() : QString();
    case D::FieldNameRole:
      return fieldLabel(column);
    default:
      return {};
  }
}

// The name of a spin-box column in the editor's messages: the header's symbol in words, with the unit.
QString ToolTableModel::fieldLabel(int column) const {
  switch (column) {
    case Teeth:
      return tr("Teeth");
    case Diameter:
      return tr("Diameter D [%1]").arg(lengthUnit());
    case Helix:
      return tr("Helix angle [°]");
    case RadialDepth:
      return tr("Radial depth a [%1]").arg(lengthUnit());
    case MaxForce:
      return tr("Allowable force F_allow [%1]").arg(DisplayUnits::of(units_).symbol(Quantity::Force));
    default:  // the cutting coefficients: their headers are their names
      return headerData(column, Qt::Horizontal).toString();
  }
}

QString ToolTableModel::toolTip(const app::ToolSpec& t, int column) const {
  switch (column) {
    case Id:
      return tr("Tool id (unique, non-empty)");
    case Teeth:
      return tr("Number of teeth (integer in [1, 100])");
    case Diameter:
      return tr("Tool diameter D [%1] (> 0)").arg(lengthUnit());
    case Helix:
      return tr("Helix angle [deg] in (-90, 90); the SDM models the helix lag, the ZOA ignores it");
    case Pitch:
      return tr("Pitch angles [deg] from each tooth to the next in the direction of rotation: one per tooth, "
                "separated by ';', each in (0, 360), summing to 360 (e.g. 70; 110; 70; 110); "
                "empty or '%1' = uniform 360/teeth")
          .arg(uniformPitchText());
    case Runout:
      return tr("Radial runout [µm] of each cutting edge: one per tooth, separated by ';', each |value| < D/4 "
                "(e.g. 0; 8; 0; -5); empty or '%1' = no runout")
          .arg(noRunoutText());
    case Kt:
    case Kr:
    case Kte:
    case Kre:
    case Ka:
    case Kae:
      return coefficientTip(column);
    case RadialDepth:
      return tr("Radial depth of cut a [%1] in (0, D]; empty = the operation's radial engagement").arg(lengthUnit());
    case MaxForce: {
      const ShopUnits& units = DisplayUnits::of(units_);
      const double fallback = project_.toolForceLimitN(app::ToolSpec{});
      const QString limit =
          tr("Allowable peak resultant force F_allow [%1] in (0, %2] (Rule 3, tool breakage)")
              .arg(units.symbol(Quantity::Force), app::formatNumber(units.fromBase(Quantity::Force, 1e7)));
      return std::isfinite(fallback) ? tr("%1; empty = the control section's breakage limit %2 %3")
                                           .arg(limit, app::formatNumber(units.fromBase(Quantity::Force, fallback)),
                                                units.symbol(Quantity::Force))
                                     : tr("%1; empty = no limit").arg(limit);
    }
    case ModesX:
      return tr("%n mode(s) in x; edit them in the mode tables below", nullptr, int(t.modes_x.size()));
    case ModesY:
      return tr("%n mode(s) in y; edit them in the mode tables below", nullptr, int(t.modes_y.size()));
    default:
      return {};
  }
}

QString ToolTableModel::coefficientTip(int column) const {
  const std::optional<app::MaterialSpec>& m = project_.material;
  // An absent edge or axial coefficient of the material is 0.
  const auto value = [](const std::optional<double>& v) { return app::formatNumber(v.value_or(0.0)); };
  QString what, material;
  switch (column) {
    case Kt:
      what = tr("Specific tangential cutting force K_t [N/mm²] (> 0)");
      if (m) material = app::formatNumber(m->Kt_N_mm2);
      break;
    case Kr:
      what = tr("Radial force ratio K_r = F_r / F_t (>= 0)");
      if (m) material = app::formatNumber(m->Kr);
      break;
    case Kte:
      what = tr("Tangential edge force K_te [N/mm] in [0, 1e4]");
      if (m) material = value(m->Kte_N_mm);
      break;
    case Kre:
      what = tr("Radial edge force K_re [N/mm] in [0, 1e4]");
      if (m) material = value(m->Kre_N_mm);
      break;
    case Ka:
      what = tr("Axial cutting coefficient K_a [N/mm²] in [0, 1e5]");
      if (m) material = value(m->Ka_N_mm2);
      break;
    case Kae:
      what = tr("Axial edge force K_ae [N/mm] in [0, 1e4]");
      if (m) material = value(m->Kae_N_mm);
      break;
    default:
      return {};
  }
  return m ? tr("%1; empty = the material's %2").arg(what, material) : tr("%1; empty = the material's").arg(what);
}

QVariant ToolTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const app::ToolSpec& t = project_.tools[std::size_t(index.row())];
  const int column = index.column();
  switch (role) {
    case Qt::DisplayRole: {
      const QVariant v = editValue(t, column);
      if (!v.isValid()) return QString();
      return v.typeId() == QMetaType::Double ? number(v.toDouble()) : v.toString();
    }
    case Qt::EditRole:
      return editValue(t, column);
    case Qt::ToolTipRole:
      return toolTip(t, column);
    case Qt::TextAlignmentRole:
      return column == Id ? QVariant(Qt::AlignLeft | Qt::AlignVCenter) : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    default:
      return role >= RangeDelegate::MinimumRole ? rangeData(column, role) : QVariant();
  }
}

QVariant ToolTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal) return QAbstractTableModel::headerData(section, orientation, role);
  // Short headers with their units (the tools dock is narrow); the tooltips name them in full.
  const QString unit = lengthUnit();
  if (role == Qt::DisplayRole) {
    switch (section) {
      case Id:
        return tr("id");
      case Teeth:
        return tr("teeth");
      case Diameter:
        return tr("D [%1]").arg(unit);
      case Helix:
        return tr("helix [°]");
      case Pitch:
        return tr("pitch [°]");
      case Runout:
        return tr("runout [µm]");
      case Kt:
        return tr("K_t [N/mm²]");
      case Kr:
        return tr("K_r [-]");
      case Kte:
        return tr("K_te [N/mm]");
      case Kre:
        return tr("K_re [N/mm]");
      case Ka:
        return tr("K_a [N/mm²]");
      case Kae:
        return tr("K_ae [N/mm]");
      case RadialDepth:
        return tr("a [%1]").arg(unit);
      case MaxForce:
        return tr("F_allow [%1]").arg(DisplayUnits::of(units_).symbol(Quantity::Force));
      case ModesX:
        return tr("modes x");
      case ModesY:
        return tr("modes y");
      default:
        return {};
    }
  }
  if (role == Qt::ToolTipRole) return toolTip(app::ToolSpec{}, section);
  return {};
}

Qt::ItemFlags ToolTableModel::flags(const QModelIndex& index) const {
  if (!index.isValid()) return Qt::NoItemFlags;
  Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled;
  if (index.column() != ModesX && index.column() != ModesY) f |= Qt::ItemIsEditable;
  return f;
}

bool ToolTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
  if (role != Qt::EditRole || !index.isValid() || index.row() >= rowCount()) return false;
  const int column = index.column();
  if (column == ModesX || column == ModesY) return false;
  if (editValue(project_.tools[std::size_t(index.row())], column) == value) return true;
  app::Project edited = project_;
  app::ToolSpec& t = edited.tools[std::size_t(index.row())];
  const QString oldId = t.id;
  const auto optional = [&](std::optional<double>& field, bool length) {
    field = value.isValid() && !value.toString().isEmpty()
                ? std::optional<double>(length ? toMm(value.toDouble()) : value.toDouble())
                : std::nullopt;
  };
  bool ok = true, integral = true;
  const QString path = QString("tools[%1].%2").arg(index.row()).arg(fieldName(column));
  QString listError;
  switch (column) {
    case Id:
      t.id = value.toString().trimmed();
      break;
    case Teeth: {
      const double teeth = value.toDouble(&ok);
      integral = ok && teeth == std::floor(teeth) && std::abs(teeth) < 1e6;
      t.teeth = integral ? static_cast<int>(teeth) : 0;
      break;
    }
    case Diameter:
      t.diameter_mm = toMm(value.toDouble(&ok));
      break;
    case Helix:
      t.helix_deg = value.toDouble(&ok);
      break;
    case Pitch:
      listError = readToothList(value, path, uniformPitchText(), t.pitch_deg);
      break;
    case Runout:
      listError = readToothList(value, path, noRunoutText(), t.runout_um);
      break;
    case Kt:
      optional(t.Kt_N_mm2, false);
      break;
    case Kr:
      optional(t.Kr, false);
      break;
    case Kte:
      optional(t.Kte_N_mm, false);
      break;
    case Kre:
      optional(t.Kre_N_mm, false);
      break;
    case Ka:
      optional(t.Ka_N_mm2, false);
      break;
    case Kae:
      optional(t.Kae_N_mm, false);
      break;
    case RadialDepth:
      optional(t.radial_depth_mm, true);
      break;
    case MaxForce:
      optional(t.max_force_N, false);
      if (t.max_force_N) *t.max_force_N = DisplayUnits::of(units_).toBase(Quantity::Force, *t.max_force_N);
      break;
    default:
      return false;
  }
  QString error =
      !listError.isEmpty() ? listError
      : !ok                ? QString("%1 = '%2': not a number").arg(path, value.toString())
      : !integral ? QString("%1 = %2: must be an integer %3").arg(path, value.toString(), app::rules::kTeeth.range())
                  : app::projectValidationError(edited);
  if (!error.isEmpty()) {
    emit editRefused(error);
    return false;
  }
  if (t == project_.tools[std::size_t(index.row())]) return true;  // "" for "uniform": nothing to undo
  emit editRequested(edited, tr("Edit %1 of tool %2").arg(fieldName(column), oldId));
  return true;
}

QString ToolTableModel::readToothList(const QVariant& value, const QString& path, const QString& absentWord,
                                      std::optional<std::vector<double>>& list) {
  const QString text = value.isValid() ? value.toString().trimmed() : QString();
  if (text.isEmpty() || text.compare(absentWord, Qt::CaseInsensitive) == 0) {
    list.reset();
    return {};
  }
  const app::ToothListParse parsed = app::parseToothList(text);
  if (!parsed.ok())
    return tr("%1 = '%2': value %3 ('%4') is not a number (one number per tooth, separated by ';'; empty or '%5' "
              "for none)")
        .arg(path, text)
        .arg(parsed.bad_item + 1)
        .arg(parsed.bad_text, absentWord);
  list = parsed.values;
  return {};
}

}  // namespace mx::widgets
