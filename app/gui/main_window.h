#pragma once
// MillExpert main window: a host of features (window_feature.h). It keeps the project document
// (undo/redo, autosave, recovery), the display units, the engine thread, the menus and the status
// bar. Each feature (lobes and the operating point, the editors, the simulation, the expert ranking,
// the Pareto study, force control, machining, the supervisor and help) owns its docks, runner and
// generation counters; it takes each project change and requests edits, which the window applies.
#include <QMainWindow>
#include <utility>
#include <vector>

#include "display_units.h"
#include "document/project_document.h"

namespace mx::widgets {
class ShopUnitsDialog;
}

namespace mx::gui {

class EditorsFeature;
class EngineRunner;
class FeatureContext;
class HelpFeature;
class TapTestFeature;
class WindowFeature;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  enum class RecoveryPolicy { Ask, Recover, Discard };
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  bool openProject(const QString& path);  // false (and a message unless quiet) on a bad file
  bool saveProject(const QString& path = {});
  const app::Project* project() const { return &doc_.project(); }
  app::ProjectDocument* document() { return &doc_; }
  widgets::DisplayUnits* units() { return &units_; }
  // Edit > Preferences...: the shop-units page, window-modal; accepting it applies the units and
  // remembers them for the user (QSettings). Returns the open dialog (tests).
  widgets::ShopUnitsDialog* openPreferences();
  void setQuiet(bool quiet) { quiet_ = quiet; }  // no modal dialogs (tests, scripts)
  void setRecoveryPolicy(RecoveryPolicy policy) { recovery_ = policy; }

 protected:
  void closeEvent(QCloseEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  // main_window.cpp
  void addFeature(WindowFeature* feature);
  void connectHelp(HelpFeature* help, EditorsFeature* editors, TapTestFeature* tap_test);
  void applyFeatureEdit(const WindowFeature* feature, const app::Project& edited, const QString& description,
                        int gesture);
  void onProjectChanged(app::ProjectChanges changes);
  void stopFeatures();
  void showError(const QString& title, const QString& message);
  // main_window_actions.cpp
  void buildActions();
  void addUndoButtons(QToolBar* bar);
  void applyDefaultDockSizes();
  void showWholeTabTitles();
  void updateRecentMenu();
  void addRecentFile(const QString& path);
  // main_window_file.cpp
  void replaceProject();
  void onNew();
  void onOpen();
  bool onSave();
  bool onSaveAs();
  bool maybeSave();
  void updateTitle();

  app::ProjectDocument doc_;
  widgets::DisplayUnits units_;
  EngineRunner* engine_;
  FeatureContext* context_;
  std::vector<WindowFeature*> features_;  // in the order they take a project change
  // The last feature gesture (one slider drag) and the document gesture its edits merge into.
  std::pair<const WindowFeature*, int> feature_gesture_{nullptr, 0};
  int document_gesture_ = 0;
  QMenu* recent_menu_ = nullptr;
  widgets::ShopUnitsDialog* preferences_ = nullptr;
  bool quiet_ = false;
  bool default_layout_pending_ = false;  // no saved layout: the default sizes on the first show
  RecoveryPolicy recovery_ = RecoveryPolicy::Ask;
};

}  // namespace mx::gui
