// MainWindow: the menus, the toolbar, their shortcuts, and the recent files. Features add their own
// actions to the File and View menus and to the toolbar.
#include <QDockWidget>
#include <QFileInfo>
#include <QMenuBar>
#include <QSettings>
#include <QTabBar>
#include <QToolBar>
#include <QUndoStack>
#include <utility>

#include "main_window.h"
#include "shop_units_dialog.h"
#include "shop_units_settings.h"
#include "window_feature.h"

namespace mx::gui {

void MainWindow::buildActions() {
  QToolBar* bar = addToolBar(tr("Main"));
  bar->setObjectName("mainToolbar");
  auto add = [&](QMenu* menu, const QString& text, const QKeySequence& key, const QString& tip, auto slot,
                 bool toolbar = false) {
    QAction* a = menu->addAction(text);
    a->setShortcut(key);
    a->setToolTip(tip);
    a->setStatusTip(tip);
    connect(a, &QAction::triggered, this, slot);
    if (toolbar) bar->addAction(a);
    return a;
  };
  QMenu* file = menuBar()->addMenu(tr("&File"));
  add(
      file, tr("&New project"), QKeySequence::New, tr("Start an empty project"), [this] { onNew(); }, true);
  add(
      file, tr("&Open project..."), QKeySequence::Open, tr("Open a MillExpert project (.mxproj)"), [this] { onOpen(); },
      true);
  recent_menu_ = file->addMenu(tr("Open &recent"));
  add(
      file, tr("&Save"), QKeySequence::Save, tr("Save the project (atomically)"), [this] { onSave(); }, true);
  add(file, tr("Save &as..."), QKeySequence::SaveAs, tr("Save the project under a new name"), [this] { onSaveAs(); });
  file->addSeparator();
  for (WindowFeature* feature : features_) feature->addFileActions(file, bar);
  file->addSeparator();
  add(file, tr("&Quit"), QKeySequence::Quit, tr("Quit MillExpert"), [this] { close(); });

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = doc_.undoStack()->createUndoAction(this, tr("&Undo"));
  undo->setShortcut(QKeySequence::Undo);
  undo->setToolTip(tr("Undo the last edit or point move"));
  QAction* redo = doc_.undoStack()->createRedoAction(this, tr("&Redo"));
  redo->setShortcut(QKeySequence::Redo);
  redo->setToolTip(tr("Redo"));
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  const QString units_tip =
      tr("Shop units: mm or inch, m/min or SFM, mm/min or IPM, W, kW or hp, N or lbf, cm\u00b3/min or in\u00b3/min");
  add(edit, tr("&Preferences..."), QKeySequence::Preferences, units_tip, [this] { openPreferences(); });
  bar->addSeparator();
  addUndoButtons(bar);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  bar->addSeparator();
  for (WindowFeature* feature : features_) feature->addViewActions(view, bar);
  view->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>()) view->addAction(dock->toggleViewAction());

  QMenu* settings_menu = menuBar()->addMenu(tr("&Settings"));
  settings_menu->setObjectName("settingsMenu");
  add(settings_menu, tr("Shop &units..."), QKeySequence(), units_tip, [this] { openPreferences(); });
  for (WindowFeature* feature : features_) feature->addSettingsActions(settings_menu);

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  for (WindowFeature* feature : features_) feature->addHelpActions(help);

  QSettings settings;
  restoreGeometry(settings.value("window/geometry").toByteArray());
  default_layout_pending_ = !restoreState(settings.value("window/state").toByteArray());
  updateRecentMenu();
}

// Toolbar buttons of fixed text: the menu's "Undo <edit>" would resize the button with every edit and
// shift the buttons after it. What they undo and redo is in their tooltips.
void MainWindow::addUndoButtons(QToolBar* bar) {
  QUndoStack* stack = doc_.undoStack();
  const auto button = [&](const QString& text, const char* name, void (QUndoStack::*slot)()) {
    QAction* a = bar->addAction(text, stack, slot);
    a->setObjectName(name);
    return a;
  };
  QAction* undo = button(tr("Undo"), "toolbarUndo", &QUndoStack::undo);
  QAction* redo = button(tr("Redo"), "toolbarRedo", &QUndoStack::redo);
  const auto follow = [this, stack, undo, redo] {
    undo->setEnabled(stack->canUndo());
    redo->setEnabled(stack->canRedo());
    undo->setToolTip(stack->canUndo() ? tr("Undo %1").arg(stack->undoText()) : tr("Nothing to undo"));
    redo->setToolTip(stack->canRedo() ? tr("Redo %1").arg(stack->redoText()) : tr("Nothing to redo"));
  };
  connect(stack, &QUndoStack::indexChanged, this, follow);
  connect(stack, &QUndoStack::cleanChanged, this, follow);
  follow();
}

// Without a saved layout: the chart keeps most of the height, the bottom docks about a third and the
// side docks about a quarter of the width each (at 1920 x 1080: a 580 px tall chart area).
void MainWindow::applyDefaultDockSizes() {
  QList<QDockWidget*> bottom, sides;
  for (QDockWidget* dock : findChildren<QDockWidget*>()) {
    if (dock->isFloating() || !dock->toggleViewAction()->isChecked()) continue;
    const Qt::DockWidgetArea area = dockWidgetArea(dock);
    if (area == Qt::BottomDockWidgetArea) bottom << dock;
    if (area == Qt::LeftDockWidgetArea || area == Qt::RightDockWidgetArea) sides << dock;
  }
  resizeDocks(bottom, QList<int>(bottom.size(), height() * 34 / 100), Qt::Vertical);
  resizeDocks(sides, QList<int>(sides.size(), width() * 23 / 100), Qt::Horizontal);
}

void MainWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  if (std::exchange(default_layout_pending_, false)) applyDefaultDockSizes();
  showWholeTabTitles();
}

// The tabs of tabbed docks keep their whole titles ("Operating point", not "Operating po..."); when
// they do not fit, the bar scrolls.
void MainWindow::showWholeTabTitles() {
  for (QTabBar* bar : findChildren<QTabBar*>(Qt::FindDirectChildrenOnly)) {
    bar->setElideMode(Qt::ElideNone);
    bar->setUsesScrollButtons(true);
  }
}

widgets::ShopUnitsDialog* MainWindow::openPreferences() {
  if (!preferences_) {
    preferences_ = new widgets::ShopUnitsDialog(this);
    connect(preferences_, &QDialog::accepted, this, [this] {
      units_.setShop(preferences_->shopUnits());
      QSettings settings;
      widgets::writeShopUnits(settings, units_.shop());
    });
  }
  preferences_->setShopUnits(units_.shop());
  preferences_->open();
  return preferences_;
}

void MainWindow::addRecentFile(const QString& path) {
  QSettings settings;
  QStringList files = settings.value("recentFiles").toStringList();
  const QString absolute = QFileInfo(path).absoluteFilePath();
  files.removeAll(absolute);
  files.prepend(absolute);
  while (files.size() > 8) files.removeLast();
  settings.setValue("recentFiles", files);
  updateRecentMenu();
}

void MainWindow::updateRecentMenu() {
  if (!recent_menu_) return;
  recent_menu_->clear();
  const QStringList files = QSettings().value("recentFiles").toStringList();
  for (const QString& f : files) {
    QAction* a = recent_menu_->addAction(QFileInfo(f).fileName(), this, [this, f] {
      if (maybeSave()) openProject(f);
    });
    a->setToolTip(f);
  }
  recent_menu_->setEnabled(!files.isEmpty());
}

}  // namespace mx::gui
