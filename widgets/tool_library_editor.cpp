#include "tool_library_editor.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QJsonArray>
#include <QScrollBar>
#include <QVBoxLayout>
#include <algorithm>

#include "cam_tool_summary.h"
#include "document/project_validation.h"
#include "flow_layout.h"
#include "input_feedback.h"
#include "range_delegate.h"

namespace mx::widgets {

namespace {

QPushButton* button(const QString& text, const QString& tip, QWidget* parent) {
  auto* b = new QPushButton(text, parent);
  b->setToolTip(tip);
  return b;
}

QLabel* errorLabel(QWidget* parent) {
  auto* l = new QLabel(parent);
  l->setStyleSheet("color: #c00000;");
  l->setWordWrap(true);
  l->setTextInteractionFlags(Qt::TextSelectableByMouse);
  l->setToolTip(QObject::tr("Why the last edit was refused; the project keeps its previous value"));
  l->hide();
  return l;
}

void setError(QLabel* label, const QString& text) {
  label->setText(text);
  label->setVisible(!text.isEmpty());
}

}  // namespace

ToolLibraryEditor::ToolLibraryEditor(QWidget* parent)
    : QWidget(parent),
      tools_(new ToolTableModel(this)),
      modesX_(new ModeTableModel(Axis::X, this)),
      modesY_(new ModeTableModel(Axis::Y, this)),
      toolView_(new QTableView(this)),
      picture_(new ToolPictureWidget(this)),
      camData_(new QLabel(this)),
      toolError_(errorLabel(this)),
      modeError_(errorLabel(this)),
      modeBox_(new QGroupBox(tr("Modes"), this)) {
  auto* add = button(tr("Add tool"), tr("Add a new tool to the library (undoable)"), this);
  duplicate_ = button(tr("Duplicate"), tr("Add a copy of the selected tool (undoable)"), this);
  remove_ = button(tr("Remove"), tr("Remove the selected tool from the library (undoable)"), this);
  auto* importButton = button(tr("Import library…"),
                              tr("Replace or extend the library from a Fusion 360, FreeCAD, LinuxCNC, CSV or JSON "
                                 "tool library"),
                              this);
  auto* exportButton =
      button(tr("Export library…"), tr("Write the library for Fusion 360, FreeCAD, LinuxCNC, CSV or JSON"), this);
  connect(add, &QPushButton::clicked, this, &ToolLibraryEditor::addTool);
  connect(duplicate_, &QPushButton::clicked, this, &ToolLibraryEditor::duplicateTool);
  connect(remove_, &QPushButton::clicked, this, &ToolLibraryEditor::removeTool);
  connect(importButton, &QPushButton::clicked, this, &ToolLibraryEditor::importRequested);
  connect(exportButton, &QPushButton::clicked, this, &ToolLibraryEditor::exportRequested);

  auto* buttons = new FlowLayout;  // wraps in a narrow dock: every button stays whole
  buttons->setObjectName("toolButtons");
  for (QPushButton* b : {add, duplicate_, remove_, importButton, exportButton}) buttons->addWidget(b);

  toolView_->setModel(tools_);
  toolView_->setItemDelegate(new RangeDelegate(toolView_));
  toolView_->setSelectionBehavior(QAbstractItemView::SelectRows);
  toolView_->setSelectionMode(QAbstractItemView::SingleSelection);
  toolView_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                             QAbstractItemView::AnyKeyPressed);
  toolView_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  toolView_->verticalHeader()->hide();
  // Three rows stay visible in a short dock (the editor scrolls instead).
  toolView_->setMinimumHeight(3 * toolView_->verticalHeader()->defaultSectionSize() +
                              toolView_->horizontalHeader()->sizeHint().height() +
                              toolView_->horizontalScrollBar()->sizeHint().height() + 2 * toolView_->frameWidth());
  toolView_->setToolTip(
      tr("The tool library; double-click a cell to edit it (empty K_t / K_r / radial depth: "
         "the material's / operation's value applies)"));
  connect(toolView_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
          &ToolLibraryEditor::onSelectionChanged);
  connect(tools_, &QAbstractItemModel::modelReset, this, &ToolLibraryEditor::onSelectionChanged);

  auto* modes = new QHBoxLayout(modeBox_);
  modes->addWidget(buildModePane(Axis::X));
  modes->addWidget(buildModePane(Axis::Y));
  modeBox_->setToolTip(tr("The modal parameters of the selected tool (tool-point FRF), per axis"));

  // Refusals are shown at once under the edited cell (the view's current one) and kept under the table
  // they come from; a good edit clears the message.
  const auto refuseIn = [this](QLabel* label, QTableView* view) {
    return [this, label, view](const QString& reason) {
      showError({});
      error_ = reason;
      setError(label, reason);
      showInputNote(view, view->currentIndex(), tr("%1. The cell keeps its value.").arg(reason));
    };
  };
  const auto forward = [this](const app::Project& edited, const QString& text) { request(edited, text); };
  connect(tools_, &ToolTableModel::editRequested, this, forward);
  connect(tools_, &ToolTableModel::editRefused, this, refuseIn(toolError_, toolView_));
  for (Axis axis : {Axis::X, Axis::Y}) {
    connect(modeModel(axis), &ModeTableModel::editRequested, this, forward);
    connect(modeModel(axis), &ModeTableModel::editRefused, this, refuseIn(modeError_, modeView(axis)));
  }

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(buttons);
  layout->addWidget(toolView_, 2);
  layout->addWidget(toolError_);
  camData_->setObjectName("camData");
  camData_->setWordWrap(true);
  layout->addWidget(camData_);
  layout->addWidget(picture_);  // under the table: the tools dock is narrow
  layout->addWidget(modeBox_, 1);
  layout->addWidget(modeError_);
  onSelectionChanged();
}

QWidget* ToolLibraryEditor::buildModePane(Axis axis) {
  ModeTableModel* model = modeModel(axis);
  const QString name = model->axisName();
  auto* pane = new QWidget(this);
  auto* view = new QTableView(pane);
  view->setModel(model);
  view->setItemDelegate(new RangeDelegate(view));
  view->setSelectionBehavior(QAbstractItemView::SelectRows);
  // Columns as wide as their short headers and values, the last one filling the rest.
  view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  view->horizontalHeader()->setStretchLastSection(true);
  view->verticalHeader()->hide();  // the rows need no numbers: three columns fit the half dock
  view->setToolTip(tr("Modes of the selected tool in %1; an empty table is a rigid axis").arg(name));
  (axis == Axis::X ? modeViewX_ : modeViewY_) = view;
  auto* add = button(tr("Add %1 mode").arg(name), tr("Add a mode in %1 to the selected tool").arg(name), pane);
  auto* remove = button(tr("Remove %1 mode").arg(name), tr("Remove the selected mode in %1").arg(name), pane);
  connect(add, &QPushButton::clicked, model, &ModeTableModel::addMode);
  connect(remove, &QPushButton::clicked, this, [model, view] {
    const QModelIndex current = view->currentIndex();
    if (current.isValid()) model->removeMode(current.row());
  });
  auto* title = new QLabel(tr("%1 direction").arg(name), pane);
  title->setWordWrap(true);  // a tap test's file name wraps instead of widening the dock
  title->setToolTip(tr("Modes of the tool-point FRF in the feed-normal plane, axis %1").arg(name));
  (axis == Axis::X ? titleX_ : titleY_) = title;
  auto* buttons = new FlowLayout;
  buttons->addWidget(add);
  buttons->addWidget(remove);
  auto* layout = new QVBoxLayout(pane);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(title);
  layout->addWidget(view);
  layout->addLayout(buttons);
  return pane;
}

void ToolLibraryEditor::setProject(const app::Project& project) {
  const QString keep = pendingSelect_.isEmpty() ? currentToolId() : pendingSelect_;
  const int oldRow = toolView_->currentIndex().row();
  pendingSelect_.clear();
  refreshing_ = true;  // one toolSelected at the end, none for the transient empty selection of a reset
  tools_->setProject(project);
  modesX_->setProject(project);
  modesY_->setProject(project);
  if (!selectTool(keep) && tools_->rowCount() > 0 && !toolView_->currentIndex().isValid())
    toolView_->setCurrentIndex(tools_->index(std::clamp(oldRow, 0, tools_->rowCount() - 1), 0));
  refreshing_ = false;
  onSelectionChanged();
}

// An axis with a tap test says so: its lobes can run on the measured FRF even without modes.
void ToolLibraryEditor::showTapTests(const app::ToolSpec* tool) {
  for (const auto& [title, axis] : {std::pair{titleX_, QString("x")}, {titleY_, QString("y")}}) {
    const std::optional<app::FrfRefSpec>* ref = nullptr;
    if (tool) ref = axis == "x" ? &tool->frf_x : &tool->frf_y;
    title->setText(ref && *ref
                       ? tr("%1 direction, tap test %2, dataset %3").arg(axis, (*ref)->file).arg((*ref)->datasetIndex())
                       : tr("%1 direction").arg(axis));
  }
}

void ToolLibraryEditor::setUnits(DisplayUnits* units) {
  tools_->setUnits(units);
  units_ = units;
  picture_->setUnits(units);
  if (units) connect(units, &DisplayUnits::changed, this, [this] { showCamData(project().findTool(currentToolId())); });
}

QString ToolLibraryEditor::currentToolId() const {
  return tools_->idAt(toolView_->currentIndex().row());
}

bool ToolLibraryEditor::selectTool(const QString& id) {
  const int row = id.isEmpty() ? -1 : tools_->rowOf(id);
  if (row < 0) return false;
  if (toolView_->currentIndex().row() != row) {
    const int column = std::max(0, toolView_->currentIndex().column());
    toolView_->setCurrentIndex(tools_->index(row, column));
  }
  return true;
}

void ToolLibraryEditor::onSelectionChanged() {
  if (refreshing_) return;
  const QString id = currentToolId();
  modesX_->setToolId(id);
  modesY_->setToolId(id);
  modeBox_->setTitle(id.isEmpty() ? tr("Modes (no tool selected)") : tr("Modes of tool %1").arg(id));
  modeBox_->setEnabled(!id.isEmpty());
  showTapTests(project().findTool(id));
  const app::ToolSpec* tool = project().findTool(id);
  if (tool) {
    picture_->setTool(*tool);
  } else {
    picture_->clear();
  }
  showCamData(tool);
  duplicate_->setEnabled(!id.isEmpty());
  remove_->setEnabled(!id.isEmpty());
  if (id != selected_) {
    selected_ = id;
    emit toolSelected(id);
  }
}

void ToolLibraryEditor::showCamData(const app::ToolSpec* tool) {
  const QString summary = tool ? camToolSummary(*tool, units_) : QString();
  camData_->setText(summary);
  camData_->setToolTip(tool ? cuttingPresetsText(*tool, units_) : QString());
  camData_->setVisible(!summary.isEmpty());
}

void ToolLibraryEditor::showError(const QString& reason) {
  error_ = reason;
  setError(toolError_, reason);
  setError(modeError_, {});
}

void ToolLibraryEditor::request(const app::Project& edited, const QString& description, const QString& select) {
  const QString error = app::projectValidationError(edited);
  if (!error.isEmpty()) {
    showError(error);
    return;
  }
  showError({});
  pendingSelect_ = select;
  emit editRequested(edited, description);
}

QString ToolLibraryEditor::uniqueId(const QString& stem) const {
  if (stem != "T" && tools_->rowOf(stem) < 0) return stem;
  for (int n = stem == "T" ? 1 : 2;; ++n) {
    QString id = QString("%1%2%3").arg(stem, stem == "T" ? "" : "-").arg(n);
    if (tools_->rowOf(id) < 0) return id;
  }
}

void ToolLibraryEditor::addTool() {
  app::Project edited = project();
  app::ToolSpec t;
  t.id = uniqueId("T");
  t.teeth = 2;
  t.diameter_mm = 10.0;
  if (edited.operation && edited.operation->radial_depth_mm)
    t.diameter_mm = std::max(t.diameter_mm, *edited.operation->radial_depth_mm);
  t.modes_x = {app::ModeSpec{1000.0, 2.0, 10.0, {}}};
  t.modes_y = {app::ModeSpec{1000.0, 2.0, 10.0, {}}};
  edited.tools.push_back(t);
  request(edited, tr("Add tool %1").arg(t.id), t.id);
}

void ToolLibraryEditor::duplicateTool() {
  const int row = toolView_->currentIndex().row();
  if (row < 0 || row >= tools_->rowCount()) return;
  app::Project edited = project();
  app::ToolSpec copy = edited.tools[std::size_t(row)];
  copy.id = uniqueId(copy.id + "-copy");
  edited.tools.insert(edited.tools.begin() + row + 1, copy);
  request(edited, tr("Duplicate tool %1").arg(tools_->idAt(row)), copy.id);
}

void ToolLibraryEditor::removeTool() {
  const int row = toolView_->currentIndex().row();
  if (row < 0 || row >= tools_->rowCount()) return;
  app::Project edited = project();
  const QString id = edited.tools[std::size_t(row)].id;
  edited.tools.erase(edited.tools.begin() + row);
  const QString next = tools_->idAt(row + 1).isEmpty() ? tools_->idAt(row - 1) : tools_->idAt(row + 1);
  request(edited, tr("Remove tool %1").arg(id), next);
}

}  // namespace mx::widgets
