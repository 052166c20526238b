#include "mode_table_model.h"

#include <QJsonArray>
#include <QJsonObject>

#include "document/project_rules.h"
#include "document/project_validation.h"
#include "range_delegate.h"

namespace mx::widgets {

namespace {
const char* fieldName(int column) {
  static const char* kNames[] = {"freq_Hz", "damping_pct", "stiffness_N_per_um"};
  return kNames[column];
}
}  // namespace

ModeTableModel::ModeTableModel(Axis axis, QObject* parent) : QAbstractTableModel(parent), axis_(axis) {}

int ModeTableModel::toolIndex() const {
  for (std::size_t i = 0; i < project_.tools.size(); ++i) {
    if (project_.tools[i].id == toolId_) return static_cast<int>(i);
  }
  return -1;
}

const std::vector<app::ModeSpec>* ModeTableModel::modes() const {
  const int i = toolIndex();
  if (i < 0) return nullptr;
  const app::ToolSpec& t = project_.tools[std::size_t(i)];
  return axis_ == Axis::X ? &t.modes_x : &t.modes_y;
}

// Resets the rows only when their number changes, so that the view keeps its current cell.
void ModeTableModel::reshape(const app::Project& project, const QString& id) {
  const int before = rowCount();
  const bool sameTool = id == toolId_;
  project_ = project;
  toolId_ = id;
  if (sameTool && rowCount() == before) {
    if (before > 0) emit dataChanged(index(0, 0), index(before - 1, ColumnCount - 1));
    return;
  }
  beginResetModel();
  endResetModel();
}

void ModeTableModel::setProject(const app::Project& project) {
  reshape(project, toolId_);
}

void ModeTableModel::setToolId(const QString& id) {
  reshape(project_, id);
}

int ModeTableModel::rowCount(const QModelIndex& parent) const {
  const auto* m = modes();
  return parent.isValid() || !m ? 0 : static_cast<int>(m->size());
}

int ModeTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant ModeTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const app::ModeSpec& m = (*modes())[std::size_t(index.row())];
  const double values[] = {m.freq_Hz, m.damping_pct, m.stiffness_N_per_um};
  const int c = index.column();
  using D = RangeDelegate;
  switch (role) {
    case Qt::DisplayRole:
      return QString::number(values[c], 'g', 6);
    case Qt::EditRole:
      return values[c];
    case Qt::ToolTipRole:
      return headerData(c, Qt::Horizontal, Qt::ToolTipRole);
    case Qt::TextAlignmentRole:
      return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    // The rule's closed lower bound, which the box enforces; a frequency of 0 can be typed and is
    // refused with the rule's reason (f_n > 0).
    case D::MinimumRole:
      return c == Frequency ? 0.0 : c == Damping ? app::rules::kDampingPct.lo : app::rules::kStiffnessNPerUm.lo;
    case D::MaximumRole:
      return c == Frequency ? 2e4 : c == Damping ? 100.0 : 1e6;
    case D::DecimalsRole:
      return c == Frequency ? 3 : 4;
    case D::StepRole:
      return c == Frequency ? 10.0 : 0.1;
    case D::FieldNameRole:
      return c == Frequency ? tr("Frequency f_n [Hz]") : c == Damping ? tr("Damping ζ [%]") : tr("Stiffness k [N/µm]");
    default:
      return {};
  }
}

QVariant ModeTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal) return QAbstractTableModel::headerData(section, orientation, role);
  if (role == Qt::DisplayRole) {
    switch (section) {
      case Frequency:
        return tr("f [Hz]");
      case Damping:
        return tr("ζ [%]");
      case Stiffness:
        return tr("k [N/µm]");
      default:
        return {};
    }
  }
  if (role == Qt::ToolTipRole) {
    switch (section) {
      case Frequency:
        return tr("Natural frequency f_n [Hz] of this %1 mode (> 0)").arg(axisName());
      case Damping:
        return tr("Damping ratio ζ [%] of this %1 mode, in (0, 100)").arg(axisName());
      case Stiffness:
        return tr("Modal stiffness k [N/µm] of this %1 mode (> 0; 1 N/µm = 1 kN/mm)").arg(axisName());
      default:
        return {};
    }
  }
  return {};
}

Qt::ItemFlags ModeTableModel::flags(const QModelIndex& index) const {
  if (!index.isValid()) return Qt::NoItemFlags;
  return Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsEditable;
}

bool ModeTableModel::request(const app::Project& edited, const QString& description) {
  const QString error = app::projectValidationError(edited);
  if (!error.isEmpty()) {
    emit editRefused(error);
    return false;
  }
  emit editRequested(edited, description);
  return true;
}

bool ModeTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
  if (role != Qt::EditRole || !index.isValid() || index.row() >= rowCount()) return false;
  const int ti = toolIndex();
  const QString path =
      QString("tools[%1].%2[%3].%4").arg(ti).arg(modesKey()).arg(index.row()).arg(fieldName(index.column()));
  bool ok = false;
  const double v = value.toDouble(&ok);
  if (!ok) {
    emit editRefused(QString("%1 = '%2': not a number").arg(path, value.toString()));
    return false;
  }
  if (data(index, Qt::EditRole).toDouble() == v) return true;
  app::Project edited = project_;
  app::ToolSpec& t = edited.tools[std::size_t(ti)];
  app::ModeSpec& m = (axis_ == Axis::X ? t.modes_x : t.modes_y)[std::size_t(index.row())];
  double* fields[] = {&m.freq_Hz, &m.damping_pct, &m.stiffness_N_per_um};
  *fields[index.column()] = v;
  return request(edited, tr("Edit %1 of mode %2%3 of tool %4")
                             .arg(fieldName(index.column()), axisName())
                             .arg(index.row() + 1)
                             .arg(toolId_));
}

bool ModeTableModel::addMode() {
  const int ti = toolIndex();
  if (ti < 0) return false;
  app::Project edited = project_;
  auto& list = axis_ == Axis::X ? edited.tools[std::size_t(ti)].modes_x : edited.tools[std::size_t(ti)].modes_y;
  list.push_back(list.empty() ? app::ModeSpec{1000.0, 2.0, 10.0, {}} : list.back());
  return request(edited, tr("Add %1 mode to tool %2").arg(axisName(), toolId_));
}

bool ModeTableModel::removeMode(int row) {
  const int ti = toolIndex();
  if (ti < 0 || row < 0 || row >= rowCount()) return false;
  app::Project edited = project_;
  auto& list = axis_ == Axis::X ? edited.tools[std::size_t(ti)].modes_x : edited.tools[std::size_t(ti)].modes_y;
  list.erase(list.begin() + row);
  return request(edited, tr("Remove %1 mode %2 of tool %3").arg(axisName()).arg(row + 1).arg(toolId_));
}

}  // namespace mx::widgets
