#include "editors_feature.h"

#include <QDockWidget>
#include <QScrollArea>

#include "machine_operation_panel.h"
#include "tool_library_editor.h"

namespace mx::gui {

namespace {
// Dock contents scroll instead of forcing the window taller than the screen (1080p).
QDockWidget* scrollingDock(QMainWindow* window, const QString& title, const QString& name, QWidget* content) {
  auto* area = new QScrollArea;
  area->setWidget(content);
  area->setWidgetResizable(true);
  area->setFrameShape(QFrame::NoFrame);
  auto* dock = new QDockWidget(title, window);
  dock->setObjectName(name);
  dock->setWidget(area);
  window->addDockWidget(Qt::LeftDockWidgetArea, dock);
  return dock;
}
}  // namespace

EditorsFeature::EditorsFeature(QMainWindow* window, FeatureContext& context)
    : WindowFeature(window),
      tool_editor_(new widgets::ToolLibraryEditor(window)),
      machine_panel_(new widgets::MachineOperationPanel(window)) {
  setObjectName("editorsFeature");
  tool_editor_->setUnits(context.units());
  machine_panel_->setUnits(context.units());
  QDockWidget* tools = scrollingDock(window, tr("Tool library"), "toolsDock", tool_editor_);
  QDockWidget* machine = scrollingDock(window, tr("Machine and operation"), "machineDock", machine_panel_);
  window->tabifyDockWidget(tools, machine);
  tools->raise();
  auto forward = [this](const app::Project& edited, const QString& description) {
    emit editRequested(edited, description, 0);
  };
  connect(tool_editor_, &widgets::ToolLibraryEditor::editRequested, this, forward);
  connect(machine_panel_, &widgets::MachineOperationPanel::editRequested, this, forward);
  connect(tool_editor_, &widgets::ToolLibraryEditor::toolSelected, &context, &FeatureContext::setActiveTool);
}

void EditorsFeature::projectChanged(const app::Project& project, Features recompute) {
  if (!(recompute & Feature::Editors)) return;
  tool_editor_->setProject(project);
  machine_panel_->setProject(project);
}

}  // namespace mx::gui
