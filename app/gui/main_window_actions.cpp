// MainWindow: docks, menus, toolbar, shortcuts and recent files.
#include <QActionGroup>
#include <QDockWidget>
#include <QFileInfo>
#include <QFormLayout>
#include <QMenuBar>
#include <QScrollArea>
#include <QSettings>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

#include "machine_operation_panel.h"
#include "main_window.h"
#include "simulation_view.h"
#include "tool_library_editor.h"

namespace mx::gui {

namespace {
// Dock contents scroll instead of forcing the window taller than the screen (1080p).
QWidget* scrollable(QWidget* content) {
  auto* area = new QScrollArea;
  area->setWidget(content);
  area->setWidgetResizable(true);
  area->setFrameShape(QFrame::NoFrame);
  return area;
}

QDockWidget* addDock(QMainWindow* window, const QString& title, const QString& name, QWidget* content,
                     Qt::DockWidgetArea area) {
  auto* dock = new QDockWidget(title, window);
  dock->setObjectName(name);
  dock->setWidget(content);
  window->addDockWidget(area, dock);
  return dock;
}
}  // namespace

void MainWindow::buildDocks() {
  tool_editor_ = new widgets::ToolLibraryEditor(this);
  tool_editor_->setUnits(&units_);
  machine_panel_ = new widgets::MachineOperationPanel(this);
  machine_panel_->setUnits(&units_);
  sim_view_ = new widgets::SimulationView(this);

  // The point panel: active tool, feed per tooth, readouts.
  auto* point_panel = new QWidget(this);
  auto* layout = new QVBoxLayout(point_panel);
  auto* form = new QFormLayout;
  tool_combo_->setToolTip(tr("The tool whose lobes, power limit and readouts are shown"));
  method_combo_->addItems({tr("Zeroth-order approximation"), tr("Semi-discretization")});
  method_combo_->setToolTip(
      tr("Stability method: ZOA (fast, accurate at high immersion) or first-order "
         "semi-discretization (low immersion, few teeth)"));
  feed_spin_->setRange(0.001, 5.0);
  feed_spin_->setDecimals(4);
  feed_spin_->setSingleStep(0.01);
  feed_spin_->setSuffix(" mm/tooth");
  feed_spin_->setToolTip(tr("Feed per tooth of the operating point (power, MRR and simulation)"));
  form->addRow(tr("Tool:"), tool_combo_);
  form->addRow(tr("Feed per tooth:"), feed_spin_);
  layout->addLayout(form);
  layout->addWidget(readout_);
  point_panel->setMinimumWidth(300);

  addDock(this, tr("Operating point"), "pointDock", point_panel, Qt::RightDockWidgetArea);
  QDockWidget* tools = addDock(this, tr("Tool library"), "toolsDock", scrollable(tool_editor_), Qt::LeftDockWidgetArea);
  QDockWidget* machine =
      addDock(this, tr("Machine and operation"), "machineDock", scrollable(machine_panel_), Qt::LeftDockWidgetArea);
  tabifyDockWidget(tools, machine);
  tools->raise();
  addDock(this, tr("Live simulation"), "simulationDock", sim_view_, Qt::BottomDockWidgetArea);

  auto forward = [this](const app::Project& edited, const QString& description) {
    const QString error = doc_.applyEdit(edited, description);
    if (!error.isEmpty()) showError(tr("Edit refused"), error);
  };
  connect(tool_editor_, &widgets::ToolLibraryEditor::editRequested, this, forward);
  connect(machine_panel_, &widgets::MachineOperationPanel::editRequested, this, forward);
  connect(tool_editor_, &widgets::ToolLibraryEditor::toolSelected, this, &MainWindow::setActiveTool);
  connect(tool_combo_, &QComboBox::currentTextChanged, this, &MainWindow::setActiveTool);
  connect(method_combo_, &QComboBox::currentIndexChanged, this, [this](int index) {
    method_ = index == 0 ? LobeMethod::ZeroOrder : LobeMethod::SemiDiscretization;
    recomputeLobes();
  });
  connect(feed_spin_, &QDoubleSpinBox::editingFinished, this, [this] {
    app::PickedPoint p = doc_.point();
    p.feed_mm_per_tooth = units_.toMm(feed_spin_->value());
    doc_.setPoint(p);
    updatePowerLimit();
  });
  connect(&units_, &widgets::DisplayUnits::changed, this, [this] {
    feed_spin_->setSuffix(QString(" %1/tooth").arg(units_.lengthSuffix()));
    feed_spin_->setDecimals(units_.lengthDecimals());
    chart_->setLengthUnit(units_.fromMm(1.0), units_.lengthSuffix());
    onPointChanged(doc_.point());
  });
}

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
  add(
      file, tr("&Export chart..."), QKeySequence(tr("Ctrl+E")), tr("Save the lobe chart as PNG, SVG or PDF"),
      [this] { onExportChart(); }, true);
  add(file, tr("Export &report..."), QKeySequence(tr("Ctrl+R")),
      tr("Write the expert report (project, ranking, q* and q**, cost terms, figures) as PDF or HTML"),
      [this] { onExportReport(); });
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
  bar->addSeparator();
  bar->addAction(undo);
  bar->addAction(redo);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  add(
      view, tr("&Reset chart view"), QKeySequence(tr("Ctrl+0")), tr("Show the whole speed range"),
      [this] { chart_->resetView(); }, true);
  add(
      view, tr("Simulate the &point"), QKeySequence(tr("F5")), tr("Run the time-domain simulation of the point"),
      [this] { startSimulation(); }, true);
  QAction* heat = view->addAction(tr("Show tool-cost &heat map"));
  heat->setCheckable(true);
  heat->setToolTip(tr("Colour the (N, b) plane by the tool cost C (eq. 13) of the active tool"));
  connect(heat, &QAction::toggled, this, [this](bool on) {
    show_cost_map_ = on;
    updateExpertOverlays();
  });
  QAction* grid = view->addAction(tr("Show admissible &grid"));
  grid->setCheckable(true);
  grid->setToolTip(tr("Show the admissible (N, b) grid points of the active tool"));
  connect(grid, &QAction::toggled, this, [this](bool on) {
    show_grid_ = on;
    updateExpertOverlays();
  });
  tools_menu_ = view->addMenu(tr("&Tools on the chart"));
  tools_menu_->setToolTip(tr("Choose which tools' lobes the chart shows"));
  view->addSeparator();
  auto* units = new QActionGroup(this);
  QAction* mm = view->addAction(tr("Lengths in &mm"));
  QAction* inch = view->addAction(tr("Lengths in &inch"));
  for (QAction* a : {mm, inch}) {
    a->setCheckable(true);
    units->addAction(a);
  }
  mm->setChecked(true);
  mm->setToolTip(tr("Show and enter lengths in millimetres"));
  inch->setToolTip(tr("Show and enter lengths in inches (the project file stays in mm)"));
  connect(mm, &QAction::triggered, this, [this] { units_.setLength(widgets::DisplayUnits::Length::Millimetre); });
  connect(inch, &QAction::triggered, this, [this] { units_.setLength(widgets::DisplayUnits::Length::Inch); });
  view->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>()) view->addAction(dock->toggleViewAction());
  bar->addSeparator();
  bar->addWidget(method_combo_);

  QSettings settings;
  restoreGeometry(settings.value("window/geometry").toByteArray());
  restoreState(settings.value("window/state").toByteArray());
  updateRecentMenu();
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
