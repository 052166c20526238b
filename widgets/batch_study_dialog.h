#pragma once
// File > Batch study (docs/shop-scale.md, "In the GUI"): which computation over which of the
// project's tools, which materials of the library and which machines (the project's own and those of
// other project files), the lobes' speed range, how many jobs. It emits what the user asks for (save
// the manifest, run it here, cancel, open results, add machines) and shows the host's progress and the
// merged table; the host writes, runs, reads and merges.
#include <QDialog>
#include <QStringList>
#include <vector>

#include "checked_spin_box.h"

class QComboBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace mx::widgets {

struct BatchStudyChoices {
  QStringList tools;      // the project's tool ids (all checked at first)
  QStringList materials;  // the project's material first (checked), then the library's
  QStringList machines;   // the project's machine (checked), then those added before
  int max_jobs = 1;       // the machine's cores
  QString project_name;   // for the title
};

struct BatchStudySettings {
  QString computation = "lobes";                                // lobes, rank, pareto or point
  QStringList tools;                                            // checked, in the list's order
  QStringList materials;                                        // checked, in the list's order
  QStringList machines;                                         // checked, in the list's order
  double from_rpm = 4000.0, to_rpm = 18000.0, step_rpm = 50.0;  // lobes only
  QString method = "zoa";                                       // lobes only: zoa or sdm
  int jobs = 1;
  bool operator==(const BatchStudySettings&) const = default;
};

class BatchStudyDialog : public QDialog {
  Q_OBJECT
 public:
  explicit BatchStudyDialog(QWidget* parent = nullptr);

  void setChoices(const BatchStudyChoices& choices);
  // Machines read from other project files, appended checked (labels already listed are skipped).
  void addMachines(const QStringList& labels);
  BatchStudySettings settings() const;
  void setSettings(const BatchStudySettings& settings);

  // The host's side: a run in progress (Run off, Cancel on), done of total cases, a status line, and
  // the merged table (column keys of batchTableHeader(), shown with their units).
  void setRunning(bool running);
  void setProgress(qint64 done, qint64 total);
  void setStatus(const QString& text);
  void setResults(const QStringList& columns, const std::vector<QStringList>& rows);

  // For tests and the screenshots.
  QComboBox* computationBox() const { return computation_; }
  QListWidget* toolList() const { return tools_; }
  QListWidget* materialList() const { return materials_; }
  QListWidget* machineList() const { return machines_; }
  QPushButton* addMachinesButton() const { return add_machines_; }
  QPushButton* runButton() const { return run_; }
  QPushButton* cancelButton() const { return cancel_; }
  QPushButton* saveButton() const { return save_; }
  QProgressBar* progressBar() const { return progress_; }
  QTableWidget* resultsTable() const { return results_; }
  QLabel* statusLabel() const { return status_; }

  // "speed_rpm" -> "Speed [rpm]": the table's heading of a summary column.
  static QString columnTitle(const QString& key);

 signals:
  void saveRequested(const mx::widgets::BatchStudySettings& settings);
  void runRequested(const mx::widgets::BatchStudySettings& settings);
  void cancelRequested();
  void openResultsRequested();
  void addMachinesRequested();

 private:
  QWidget* buildForm();
  QWidget* buildSpeedRange();
  QWidget* buildMachines();
  void updateButtons();
  static QStringList checkedItems(const QListWidget* list);
  static void fillList(QListWidget* list, const QStringList& items, int checked_first);

  QComboBox* computation_;
  QListWidget* tools_;
  QListWidget* materials_;
  QListWidget* machines_;
  QPushButton* add_machines_;
  QWidget* speed_range_ = nullptr;
  CheckedDoubleSpinBox* from_ = nullptr;
  CheckedDoubleSpinBox* to_ = nullptr;
  CheckedDoubleSpinBox* step_ = nullptr;
  QComboBox* method_ = nullptr;
  CheckedSpinBox* jobs_ = nullptr;
  QPushButton* save_;
  QPushButton* run_;
  QPushButton* cancel_;
  QPushButton* open_;
  QProgressBar* progress_;
  QLabel* status_;
  QTableWidget* results_;
  bool running_ = false;
};

}  // namespace mx::widgets

Q_DECLARE_METATYPE(mx::widgets::BatchStudySettings)
