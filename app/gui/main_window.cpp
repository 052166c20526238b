#include "main_window.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QFile>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

#include "batch_feature.h"
#include "control_feature.h"
#include "editors_feature.h"
#include "engine_runner.h"
#include "expert_feature.h"
#include "feature_context.h"
#include "help_feature.h"
#include "lobes_feature.h"
#include "machining_feature.h"
#include "pareto_feature.h"
#include "shop_units_settings.h"
#include "simulation_feature.h"
#include "supervisor_feature.h"
#include "tap_test_feature.h"
#include "tool_library_editor.h"
#include "tool_library_transfer.h"

namespace mx::gui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      engine_(new EngineRunner(this)),
      context_(new FeatureContext(doc_, units_, engine_->pool(), this)) {
  setObjectName("MillExpertMainWindow");
  setWindowIcon(QIcon(":/icons/millexpert.svg"));
  auto* lobes = new LobesFeature(this, *context_, engine_);
  connect(lobes, &LobesFeature::cancelRequested, this, &MainWindow::stopFeatures);
  // The docks of a feature tab with those of the features before it: the order matters.
  addFeature(lobes);
  auto* editors = new EditorsFeature(this, *context_);
  addFeature(editors);
  addFeature(new SimulationFeature(this, *context_));
  auto* tap_test = new TapTestFeature(this, *context_);
  addFeature(tap_test);
  addFeature(new ExpertFeature(this, *context_, lobes->chart()));
  addFeature(new ParetoFeature(this, *context_, lobes->chart()));
  addFeature(new ControlFeature(this, *context_));
  addFeature(new MachiningFeature(this, *context_));
  addFeature(new SupervisorFeature(this, *context_));
  addFeature(new BatchFeature(this, *context_));
  auto* help = new HelpFeature(this);
  addFeature(help);
  connectHelp(help, editors, tap_test);
  buildActions();
  units_.setShop(widgets::readShopUnits(QSettings()));  // the user's; the views follow its changed()

  // The point is picked for the active tool: a save names it in operating_point, and a file that names
  // one opens on it.
  connect(context_, &FeatureContext::activeToolChanged, &doc_, &app::ProjectDocument::setPointTool);
  connect(&doc_, &app::ProjectDocument::pointToolChanged, context_, &FeatureContext::setActiveTool);
  connect(&doc_, &app::ProjectDocument::changed, this, &MainWindow::onProjectChanged);
  connect(&doc_, &app::ProjectDocument::dirtyChanged, this, &MainWindow::updateTitle);
  connect(&doc_, &app::ProjectDocument::filePathChanged, this, &MainWindow::updateTitle);
  // In the status bar only: a dialog every 30 s would stop the work it is there to protect.
  connect(&doc_, &app::ProjectDocument::autosaveFailed, this,
          [this](const QString& message) { statusBar()->showMessage(tr("Autosave failed: %1").arg(message), 30000); });
  resize(1600, 950);
  updateTitle();
  onProjectChanged(app::kAllSections);
}

MainWindow::~MainWindow() {
  stopFeatures();
  // The features, then their docks, go while doc_ is alive: QWidget's destructor deletes the children
  // only after the members, and a widget destroyed there could still call a feature that reads the
  // project (UBSan: a member call on the destroyed document, in the GUI monkey's teardown).
  for (WindowFeature* feature : features_) delete feature;
  features_.clear();
  qDeleteAll(findChildren<QDockWidget*>(Qt::FindDirectChildrenOnly));
}

// The start page's and the Examples menu's requests: the window's own open (with its save prompt),
// and the imports of the features that own them.
void MainWindow::connectHelp(HelpFeature* help, EditorsFeature* editors, TapTestFeature* tap_test) {
  connect(help, &HelpFeature::projectOpenRequested, this, [this](const QString& path) {
    if (maybeSave()) openProject(path);
  });
  connect(help, &HelpFeature::openProjectRequested, this, &MainWindow::onOpen);
  connect(help, &HelpFeature::tapTestImportRequested, tap_test, &TapTestFeature::chooseImport);
  connect(help, &HelpFeature::toolLibraryImportRequested, editors->libraryTransfer(),
          &ToolLibraryTransfer::chooseImport);
  connect(help, &HelpFeature::addToolRequested, editors->toolEditor(), &widgets::ToolLibraryEditor::addTool);
}

void MainWindow::stopFeatures() {
  for (WindowFeature* feature : features_) feature->stop();
}

void MainWindow::showError(const QString& title, const QString& message) {
  statusBar()->showMessage(title + ": " + message, 10000);
  if (!quiet_) QMessageBox::critical(this, title, message);
}

void MainWindow::addFeature(WindowFeature* feature) {
  features_.push_back(feature);
  connect(feature, &WindowFeature::editRequested, this,
          [this, feature](const app::Project& edited, const QString& description, int gesture) {
            applyFeatureEdit(feature, edited, description, gesture);
          });
  connect(feature, &WindowFeature::pointRequested, &doc_, &app::ProjectDocument::setPoint);
  connect(feature, &WindowFeature::initialPointRequested, &doc_, &app::ProjectDocument::initPoint);
  connect(feature, &WindowFeature::editWithPointRequested, this,
          [this](const app::Project& edited, const app::PickedPoint& point, const QString& description) {
            const QString error = doc_.applyEditAndMovePoint(edited, point, description);
            if (!error.isEmpty()) showError(description, error);
          });
  connect(feature, &WindowFeature::statusMessage, statusBar(), &QStatusBar::showMessage);
  connect(feature, &WindowFeature::errorRaised, this, &MainWindow::showError);
}

// The edits of one gesture of a feature (a slider drag) merge into one undo step.
void MainWindow::applyFeatureEdit(const WindowFeature* feature, const app::Project& edited, const QString& description,
                                  int gesture) {
  if (std::pair(feature, gesture) != feature_gesture_) {
    feature_gesture_ = {feature, gesture};
    document_gesture_ = gesture > 0 ? doc_.newGesture() : 0;
  }
  const QString error = doc_.applyEdit(edited, description, document_gesture_);
  if (!error.isEmpty()) showError(description, error);
}

// The project changed (edit, undo, redo, load): each feature recomputes what the changed sections
// invalidate (featuresToRecompute) and keeps its other results.
void MainWindow::onProjectChanged(app::ProjectChanges changes) {
  const Features recompute = featuresToRecompute(changes);
  for (WindowFeature* feature : features_) feature->projectChanged(doc_.project(), recompute);
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!maybeSave()) {
    event->ignore();
    return;
  }
  QSettings settings;
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  QFile::remove(doc_.autosavePath());
  event->accept();
}

}  // namespace mx::gui
