#pragma once
// The modes of one axis (x or y) of one tool as an editable table: frequency [Hz], damping [%],
// stiffness [N/µm]. Like ToolTableModel it shows a copy of the project and only requests edits:
// validated edits are emitted with editRequested(), invalid ones with editRefused(reason).
#include <QAbstractTableModel>

#include "document/project.h"

namespace mx::widgets {

class ModeTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum class Axis { X, Y };
  enum Column { Frequency, Damping, Stiffness, ColumnCount };
  explicit ModeTableModel(Axis axis, QObject* parent = nullptr);

  Axis axis() const { return axis_; }
  QString axisName() const { return axis_ == Axis::X ? QStringLiteral("x") : QStringLiteral("y"); }
  void setProject(const app::Project& project);
  void setToolId(const QString& id);  // "" = no tool (empty table)
  QString toolId() const { return toolId_; }

  // Request a new mode (a copy of the last one, or 1000 Hz / 2 % / 10 N/µm) or the removal of `row`.
  // Return false when there is no tool / row, or the edit was refused.
  bool addMode();
  bool removeMode(int row);

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
  Qt::ItemFlags flags(const QModelIndex& index) const override;
  bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

 signals:
  void editRequested(const mx::app::Project& edited, const QString& description);
  void editRefused(const QString& reason);

 private:
  int toolIndex() const;
  const std::vector<app::ModeSpec>* modes() const;
  QString modesKey() const { return axis_ == Axis::X ? QStringLiteral("modes_x") : QStringLiteral("modes_y"); }
  bool request(const app::Project& edited, const QString& description);
  void reshape(const app::Project& project, const QString& id);

  Axis axis_;
  app::Project project_;
  QString toolId_;
};

}  // namespace mx::widgets
