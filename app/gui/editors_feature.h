#pragma once
// The project's editors: the tool library and the machine and operation panel (tabbed docks on the
// left). Their edits go to the document as undoable steps; choosing a tool in the library makes it the
// active tool. The library's Import / Export go through ToolLibraryTransfer. The panel's material picker
// offers the bundled materials library.
#include <QMainWindow>

#include "feature_context.h"
#include "window_feature.h"

namespace mx::widgets {
class MachineOperationPanel;
class ToolLibraryEditor;
}  // namespace mx::widgets

namespace mx::gui {

class ToolLibraryTransfer;

class EditorsFeature : public WindowFeature {
  Q_OBJECT
 public:
  // Adds the "toolsDock" and the "machineDock".
  EditorsFeature(QMainWindow* window, FeatureContext& context);

  void projectChanged(const app::Project& project, Features recompute) override;
  widgets::ToolLibraryEditor* toolEditor() const { return tool_editor_; }
  ToolLibraryTransfer* libraryTransfer() const { return transfer_; }

 private:
  widgets::ToolLibraryEditor* tool_editor_;
  widgets::MachineOperationPanel* machine_panel_;
  ToolLibraryTransfer* transfer_;
};

}  // namespace mx::gui
