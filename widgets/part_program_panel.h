#pragma once
// Part-program override panel: the blocks of an opened NC program with the proposed feed F
// and speed S beside the programmed ones, the reason of each change, the depth of cut and the predicted
// cutting force per block; the parser warnings below; buttons to open a program and to export the
// overridden program, the CSV and (Heidenhain programs) the AFC table; the controller dialect to read
// the program in (detected by default). The main window shows the file dialogs and does the work.
// Model/view: a private table model serves the rows on demand, so a program of 100 000 blocks is set
// in milliseconds. Read-only. Unchanged proposals show "="; changed cells are highlighted. Feeds, depth
// and force are shown in the shop units of setUnits(), whatever the program's own unit (G20/G21).
#include <QPointer>
#include <QString>
#include <QVector>
#include <QWidget>
#include <optional>

#include "display_units.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;
class QTableView;

namespace mx::widgets {

struct PartProgramRow {                           // one block of the program
  int line = 0;                                   // 1-based
  QString text;                                   // the block as written (without line end)
  std::optional<double> original_feed, new_feed;  // in the program's units (see feed unit label), nullopt when none
  std::optional<double> speed_rpm, new_speed_rpm;
  // > 0 when the new value is modal: the block has no F (S) word of its own and inherits the one
  // proposed at this line.
  int new_feed_from_line = 0, new_speed_from_line = 0;
  std::optional<double> depth_mm, predicted_force_n;
  QString reason;  // empty when unchanged
  bool changed = false;
};

struct PartProgramWarningView {
  int line = 0;
  int column = 0;
  QString text;
  QString message;
};

class PartProgramTableModel;

class PartProgramPanel : public QWidget {
  Q_OBJECT
 public:
  enum Column { kLine, kBlock, kFeed, kNewFeed, kSpeed, kNewSpeed, kDepth, kForce, kReason, kColumnCount };

  explicit PartProgramPanel(QWidget* parent = nullptr);
  ~PartProgramPanel() override;

  void setProgram(const QString& path, const QVector<PartProgramRow>& rows,
                  const QVector<PartProgramWarningView>& warnings, const QString& feed_unit /* "mm/min" or "in/min" */,
                  const QString& controller);
  void clear();
  void setUnits(DisplayUnits* units);  // nullptr: metric
  void setStatus(const QString& text);
  const QVector<PartProgramRow>& rows() const;
  int changedCount() const { return changed_count_; }
  void setShowChangedOnly(bool on);  // filter checkbox
  bool showChangedOnly() const;
  QTableView* table() const { return table_; }
  QListWidget* warningList() const { return warnings_; }
  QPushButton* openButton() const { return open_button_; }
  QPushButton* exportProgramButton() const { return export_program_button_; }
  QPushButton* exportCsvButton() const { return export_csv_button_; }
  QPushButton* exportAfcButton() const { return export_afc_button_; }
  QComboBox* dialectBox() const { return dialect_box_; }
  // The dialect chosen to read programs in: "iso", "heidenhain", "sinumerik", "linuxcnc", or empty to
  // detect it.
  QString dialectChoice() const;
  void setDialectChoice(const QString& name);
  // The dialect the shown program was read in, as the header says it ("Heidenhain Klartext, detected
  // at line 1: BEGIN PGM"); afc: the AFC export applies (a Heidenhain program).
  void setDialect(const QString& description, bool afc);

  // Additions.
  bool hasProgram() const { return has_program_; }
  QString feedUnit() const { return feed_unit_; }  // the program's ("mm/min" or "in/min")
  // Selects and scrolls to the block of `line` (clears the changed-only filter when it hides it);
  // false when no block has that line.
  bool selectLine(int line);
  int selectedLine() const;  // 0 when none
  int visibleRowCount() const;
  QString headerText() const;
  QString statusText() const;
  // The colour of changed cells: new F, new S and the reason of a changed block.
  static QColor highlightColor();

 signals:
  void openRequested();                      // "Open program..." (the main window shows the file dialog)
  void exportProgramRequested();             // "Export program..." (enabled only when a program is loaded)
  void exportCsvRequested();                 // "Export CSV..."
  void exportAfcRequested();                 // "Export AFC table..." (Heidenhain programs)
  void dialectChanged(const QString& name);  // the dialect choice changed (empty: detect)
  void lineActivated(int line);              // double click on a row or a warning

 private:
  void updateHeader();
  void resizeColumns();

  PartProgramTableModel* model_;
  QPointer<DisplayUnits> units_;
  QTableView* table_;
  QListWidget* warnings_;
  QLabel* header_label_;
  QLabel* warnings_label_;
  QLabel* status_label_;
  QCheckBox* changed_only_box_;
  QPushButton* open_button_;
  QPushButton* export_program_button_;
  QPushButton* export_csv_button_;
  QPushButton* export_afc_button_;
  QComboBox* dialect_box_;
  QString path_, controller_, dialect_, feed_unit_ = QStringLiteral("mm/min");
  int changed_count_ = 0;
  bool has_program_ = false;
};

}  // namespace mx::widgets
