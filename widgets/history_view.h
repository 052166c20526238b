#pragma once
// The Rule 14 learning-database history (Pareto paper): the programmed points with the weights that
// produced them, newest first, filtered by tool, material, machine, source and an MRR band. The view does not
// touch the database: the main window queries it (app/services/learning_database.h) on filterChanged() or
// refreshRequested() and calls setRows() with the result.
//
// Signals: filterChanged() exactly once per user change of the filter widgets (combo chosen, MRR box
// toggled, MRR bound edited while the box is checked); setFilter() and the set*Choices() emit nothing.
// applyWeightsRequested() from the "Apply these weights" button or a double-click on a row, only for a
// row whose weights are the four Pareto weights (TOL, MRR, SURF, ROS). Depth, feed per tooth and MRR
// (table and band) are shown in the shop units of setUnits(); rows and filter stay in mm and cm³/s.
#include <QMetaType>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QVector>
#include <QWidget>
#include <array>
#include <optional>

#include "display_units.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace mx::widgets {

struct HistoryRow {
  qint64 id = 0;
  QString time;                    // ISO 8601
  QString tool, material, source;  // source: operator, automatic, rule, feedback
  QString machine;                 // the project's machine.name; "" when the record names none
  QVector<double> weights;         // 3 (2006 c) or 4 (Pareto: TOL, MRR, SURF, ROS)
  double speed_rpm = 0, depth_mm = 0, feed_mm_per_tooth = 0, mrr_cm3_s = 0;
  std::optional<double> tol, surf, ros;
};

struct HistoryFilter {
  QString tool, material, source;        // empty = any
  QString machine;                       // empty = any
  std::optional<double> mrr_lo, mrr_hi;  // cm³/s; both set or both unset
  bool operator==(const HistoryFilter&) const = default;
};

class HistoryView : public QWidget {
  Q_OBJECT
 public:
  enum Column {
    TimeColumn,
    ToolColumn,
    MaterialColumn,
    MachineColumn,
    SourceColumn,
    WeightColumn0,  // w_TOL (or c1), then w_MRR, w_SURF, w_ROS
    SpeedColumn = WeightColumn0 + 4,
    DepthColumn,
    FeedColumn,
    MrrColumn,
    TolColumn,
    SurfColumn,
    RosColumn,
    ColumnCount
  };

  static constexpr double kMaxMrrCm3S = 1e4;  // the largest MRR bound

  explicit HistoryView(QWidget* parent = nullptr);
  void setUnits(DisplayUnits* units);  // nullptr: metric

  void setRows(const QVector<HistoryRow>& rows);  // shown newest first as given; keeps the selection by id
  const QVector<HistoryRow>& rows() const { return rows_; }
  // Filter combos ("Any" first); no signal. The current choice is kept, even when missing from the list.
  void setToolChoices(const QStringList& tools);
  void setMaterialChoices(const QStringList& materials);
  void setMachineChoices(const QStringList& machines);
  HistoryFilter filter() const;
  void setFilter(const HistoryFilter& f);  // no signal; an MRR band is used only when both bounds are set
  int selectedRow() const;                 // -1 when none
  void selectRow(int row);                 // out of range: no selection
  void setStatus(const QString& text);     // e.g. the database path or an error

  QTableWidget* table() const { return table_; }
  QPushButton* applyButton() const { return apply_; }
  QPushButton* refreshButton() const { return refresh_; }
  QComboBox* toolCombo() const { return tool_; }
  QComboBox* materialCombo() const { return material_; }
  QComboBox* machineCombo() const { return machine_; }
  QComboBox* sourceCombo() const { return source_; }
  QCheckBox* mrrBox() const { return mrr_box_; }
  QDoubleSpinBox* mrrLoSpin() const { return mrr_lo_; }
  QDoubleSpinBox* mrrHiSpin() const { return mrr_hi_; }
  QLabel* statusLabel() const { return status_; }

 signals:
  void filterChanged(const mx::widgets::HistoryFilter& filter);
  void applyWeightsRequested(const QVector<double>& weights);
  void refreshRequested();

 private:
  static void setChoices(QComboBox* combo, const QStringList& values);
  static void selectValue(QComboBox* combo, const QString& value);  // adds a missing value; no signal
  void onMrrEdited(bool lower);
  void emitIfChanged();
  void requestApply(int row);
  void updateButtons();
  void refreshUnits();
  double shownMrr(double cm3_s) const;
  double mrrFromSpin(const QDoubleSpinBox* spin, double stored) const;

  QPointer<DisplayUnits> units_;
  std::array<double, 2> band_{0.0, 100.0};  // the MRR band last set or shown [cm³/s]
  bool band_shown_ = false;                 // the spin boxes show band_ (after the first refreshUnits)
  ShopUnits shown_units_;                   // the units the band and the rows are shown in
  QVector<HistoryRow> rows_;
  HistoryFilter last_filter_;
  QComboBox* tool_;
  QComboBox* material_;
  QComboBox* machine_;
  QComboBox* source_;
  QCheckBox* mrr_box_;
  QDoubleSpinBox* mrr_lo_;
  QDoubleSpinBox* mrr_hi_;
  QTableWidget* table_;
  QPushButton* apply_;
  QPushButton* refresh_;
  QLabel* status_;
};

}  // namespace mx::widgets

Q_DECLARE_METATYPE(mx::widgets::HistoryFilter)
