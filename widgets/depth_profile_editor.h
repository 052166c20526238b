#pragma once
// Editor of the workpiece's depth profile for the closed-loop run: a table of steps along the tool path,
// Length [mm] | Depth [mm], with rows added (a copy of the current one) and removed. An invalid cell is
// refused in place with the reason ("Row 2: Depth [mm] = -1: must be >= 0") and shows its previous
// value again; removing the last step is refused (a profile needs at least one). A valid change emits
// stepsEdited with the whole profile; setSteps() emits nothing.
#include <QString>
#include <QVector>
#include <QWidget>
#include <optional>

#include "control_data.h"

class QLabel;
class QPushButton;
class QTableWidget;
class QTableWidgetItem;

namespace mx::widgets {

class DepthProfileEditor : public QWidget {
  Q_OBJECT
 public:
  enum Column { kLength = 0, kDepth = 1 };
  static constexpr double kDefaultLengthMm = 50.0;  // the step added to an empty profile
  static constexpr double kDefaultDepthMm = 1.0;

  explicit DepthProfileEditor(QWidget* parent = nullptr);

  void setSteps(const QVector<DepthStepView>& steps);  // no signal
  QVector<DepthStepView> steps() const { return steps_; }

  // The value of a typed cell, or the reason it is refused (without the row).
  static std::optional<double> parseCell(Column column, const QString& text, QString* reason);
  static QString columnTitle(Column column);  // "Length [mm]", "Depth [mm]"

  QTableWidget* table() const { return table_; }
  QPushButton* addButton() const { return add_; }
  QPushButton* removeButton() const { return remove_; }
  QString errorText() const;
  QString summaryText() const;

 signals:
  void stepsEdited(const QVector<mx::widgets::DepthStepView>& steps);

 private:
  void onItemChanged(QTableWidgetItem* item);
  void addStep();
  void removeSteps();
  void fillTable();
  void updateSummary();
  void setError(const QString& text);

  QVector<DepthStepView> steps_;
  QTableWidget* table_;
  QPushButton* add_;
  QPushButton* remove_;
  QLabel* summary_;
  QLabel* error_;
  bool filling_ = false;
};

}  // namespace mx::widgets
