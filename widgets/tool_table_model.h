#pragma once
// The tools of a project as an editable table (one row per tool). The model shows a copy of the
// project given by setProject() and never changes it: an edit builds the edited project, validates
// it (validateProject) and emits editRequested(), or emits editRefused(reason) and keeps the old value.
// Lengths are shown and entered in the DisplayUnits (the project stays in mm).
#include <QAbstractTableModel>
#include <QPointer>

#include "display_units.h"
#include "document/project.h"

namespace mx::widgets {

class ToolTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column {
    Id,
    Teeth,
    Diameter,
    Helix,
    Pitch,
    Runout,
    Kt,
    Kr,
    Kte,
    Kre,
    Ka,
    Kae,
    RadialDepth,
    MaxForce,
    ModesX,
    ModesY,
    ColumnCount
  };
  // The text of a pitch cell for uniform pitch, and of a runout cell without runout; an empty cell
  // means the same.
  static QString uniformPitchText() { return QStringLiteral("uniform"); }
  static QString noRunoutText() { return QStringLiteral("none"); }
  explicit ToolTableModel(QObject* parent = nullptr);

  // Keeps the row structure when the number of tools is unchanged (the view keeps its selection).
  void setProject(const app::Project& project);
  const app::Project& project() const { return project_; }
  void setUnits(DisplayUnits* units);
  int rowOf(const QString& id) const;  // -1 when absent
  QString idAt(int row) const;         // "" when out of range

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
  Qt::ItemFlags flags(const QModelIndex& index) const override;
  // Validates and requests the edit; returns false (and emits editRefused) when it is refused.
  // An invalid QVariant clears an optional column (K_t, K_r, the edge and axial coefficients K_te, K_re,
  // K_a, K_ae, radial depth, maximum force). The pitch
  // and runout cells take a ';'-separated list (degrees, micrometres) or an empty cell / the word.
  bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

 signals:
  void editRequested(const mx::app::Project& edited, const QString& description);
  void editRefused(const QString& reason);

 private:
  double toDisplay(double mm) const { return units_ ? units_->fromMm(mm) : mm; }
  double toMm(double value) const { return units_ ? units_->toMm(value) : value; }
  QString lengthUnit() const { return units_ ? units_->lengthSuffix() : QStringLiteral("mm"); }
  QVariant editValue(const app::ToolSpec& tool, int column) const;
  QVariant rangeData(int column, int role) const;
  QString fieldLabel(int column) const;  // RangeDelegate::FieldNameRole
  QString toolTip(const app::ToolSpec& tool, int column) const;
  QString coefficientTip(int column) const;  // K_t .. K_ae: what the value is, and the material's
  // Reads a pitch or runout cell into `list`; returns the refusal ("" = ok).
  static QString readToothList(const QVariant& value, const QString& path, const QString& absentWord,
                               std::optional<std::vector<double>>& list);
  void refreshAll();

  app::Project project_;
  QPointer<DisplayUnits> units_;
};

}  // namespace mx::widgets
