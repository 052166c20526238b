#include "editors_feature.h"

#include <QDockWidget>

#include "feature_dock.h"
#include "machine_operation_panel.h"
#include "material_choices.h"
#include "tool_library_editor.h"
#include "tool_library_transfer.h"

namespace mx::gui {

EditorsFeature::EditorsFeature(QMainWindow* window, FeatureContext& context)
    : WindowFeature(window),
      tool_editor_(new widgets::ToolLibraryEditor(window)),
      machine_panel_(new widgets::MachineOperationPanel(window)),
      transfer_(new ToolLibraryTransfer(context, window)) {
  setObjectName("editorsFeature");
  tool_editor_->setUnits(context.units());
  machine_panel_->setUnits(context.units());
  machine_panel_->setMaterialLibrary(bundledMaterialChoices());
  QDockWidget* tools = makeFeatureDock(window, tr("Tool library"), "toolsDock", tool_editor_, DockContent::Scrolling);
  QDockWidget* machine =
      makeFeatureDock(window, tr("Machine and operation"), "machineDock", machine_panel_, DockContent::Scrolling);
  for (QDockWidget* d : {tools, machine}) window->addDockWidget(Qt::LeftDockWidgetArea, d);
  window->tabifyDockWidget(tools, machine);
  tools->raise();
  auto forward = [this](const app::Project& edited, const QString& description) {
    emit editRequested(edited, description, 0);
  };
  connect(tool_editor_, &widgets::ToolLibraryEditor::editRequested, this, forward);
  connect(machine_panel_, &widgets::MachineOperationPanel::editRequested, this, forward);
  connect(transfer_, &ToolLibraryTransfer::editRequested, this, forward);
  connect(transfer_, &ToolLibraryTransfer::importFinished, tool_editor_, [this](const QString& error) {
    tool_editor_->showError(error.isEmpty() || error == tr("cancelled")
                                ? QString()
                                : tr("Import refused, the library is unchanged: %1").arg(error));
  });
  connect(transfer_, &ToolLibraryTransfer::statusMessage, this,
          [this](const QString& text) { emit statusMessage(text, 10000); });
  connect(tool_editor_, &widgets::ToolLibraryEditor::importRequested, transfer_, &ToolLibraryTransfer::chooseImport);
  connect(tool_editor_, &widgets::ToolLibraryEditor::exportRequested, transfer_, &ToolLibraryTransfer::chooseExport);
  connect(tool_editor_, &widgets::ToolLibraryEditor::toolSelected, &context, &FeatureContext::setActiveTool);
}

void EditorsFeature::projectChanged(const app::Project& project, Features recompute) {
  if (!(recompute & Feature::Editors)) return;
  tool_editor_->setProject(project);
  machine_panel_->setProject(project);
}

}  // namespace mx::gui
