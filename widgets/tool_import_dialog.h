#pragma once
// The tools of a library file before they join the project: each with a check box (a shop's library
// holds thousands, a project at most app::rules::kMaxTools), the tools left out and why, and whether
// they replace the project's library or join it.
#include <QDialog>
#include <QStringList>
#include <vector>

#include "display_units.h"
#include "document/project.h"

class QLabel;
class QRadioButton;
class QTableView;
class QDialogButtonBox;

namespace mx::widgets {

class ToolImportDialog : public QDialog {
  Q_OBJECT
 public:
  // `skipped`: "name: reason" per tool the file holds that is not a milling cutter. `projectTools`: how
  // many tools the project has (an append must stay within the limit).
  ToolImportDialog(const QString& fileName, const std::vector<app::ToolSpec>& tools, const QStringList& skipped,
                   int projectTools, const DisplayUnits* units, QWidget* parent = nullptr);

  QStringList selectedIds() const;  // in the file's order
  bool replace() const;
  void setAllChecked(bool checked);
  void setChecked(const QString& id, bool checked);  // for tests and scripts; unknown ids are ignored

 private:
  void updateSummary();

  class Model;
  Model* model_;
  QTableView* table_;
  QLabel* summary_;
  QRadioButton* append_;
  QRadioButton* replace_;
  QDialogButtonBox* buttons_;
  int project_tools_;
};

}  // namespace mx::widgets
