#pragma once
// The tool-library editor: a table of the project's tools (edited in place), add / duplicate /
// remove, and for the selected tool its end view (teeth at their pitch angles) and its x and y modes. It shows the
// project given by setProject() and never changes it: every edit is validated (validateProject) and requested with
// editRequested(); an invalid edit is refused in place (no signal, the old value stays, the reason is shown in red
// under the edited cell at once and under the table). Its Import / Export buttons ask the window for a library
// transfer.
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QTableView>
#include <QWidget>

#include "display_units.h"
#include "document/project.h"
#include "mode_table_model.h"
#include "tool_picture_widget.h"
#include "tool_table_model.h"

class QGroupBox;

namespace mx::widgets {

class ToolLibraryEditor : public QWidget {
  Q_OBJECT
 public:
  using Axis = ModeTableModel::Axis;
  explicit ToolLibraryEditor(QWidget* parent = nullptr);

  // Shows `project` (after every document change, including undo/redo); keeps the selected tool.
  void setProject(const app::Project& project);
  const app::Project& project() const { return tools_->project(); }
  void setUnits(DisplayUnits* units);  // lengths in mm or inch; nullptr = mm

  QString currentToolId() const;                // "" when no tool is selected
  bool selectTool(const QString& id);           // false when the library has no such tool
  QString errorText() const { return error_; }  // the last refusal shown ("" after a good edit)

  ToolTableModel* toolModel() const { return tools_; }
  ModeTableModel* modeModel(Axis axis) const { return axis == Axis::X ? modesX_ : modesY_; }
  QTableView* toolView() const { return toolView_; }
  ToolPictureWidget* toolPicture() const { return picture_; }
  QLabel* camData() const { return camData_; }
  QTableView* modeView(Axis axis) const { return axis == Axis::X ? modeViewX_ : modeViewY_; }

 public slots:
  void addTool();                         // a new tool "T<n>" (2 teeth, 10 mm, one 1000 Hz mode per axis)
  void duplicateTool();                   // a copy of the selected tool after it, id "<id>-copy"
  void removeTool();                      // the selected tool
  void showError(const QString& reason);  // "" hides the message

 signals:
  void editRequested(const mx::app::Project& edited, const QString& description);
  void toolSelected(const QString& id);
  // The Import / Export buttons: the window's tool-library transfer chooses the file and the format.
  void importRequested();
  void exportRequested();

 private:
  QWidget* buildModePane(Axis axis);
  void request(const app::Project& edited, const QString& description, const QString& select = {});
  void onSelectionChanged();
  void showTapTests(const app::ToolSpec* tool);
  void showCamData(const app::ToolSpec* tool);
  QString uniqueId(const QString& stem) const;

  ToolTableModel* tools_;
  ModeTableModel* modesX_;
  ModeTableModel* modesY_;
  QTableView* toolView_;
  ToolPictureWidget* picture_;  // the end view of the selected tool
  QLabel* camData_;             // what the CAM library says about the selected tool
  DisplayUnits* units_ = nullptr;
  QTableView* modeViewX_ = nullptr;
  QTableView* modeViewY_ = nullptr;
  QLabel* titleX_ = nullptr;  // "x direction", with its tap test when the tool has one
  QLabel* titleY_ = nullptr;
  QLabel* toolError_;
  QLabel* modeError_;
  QGroupBox* modeBox_;
  QPushButton* duplicate_;
  QPushButton* remove_;
  QString error_;
  QString selected_;  // the tool id last announced by toolSelected
  QString pendingSelect_;
  bool refreshing_ = false;  // select this tool once the document shows it (after add / duplicate)
};

}  // namespace mx::widgets
