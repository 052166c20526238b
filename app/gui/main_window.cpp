#include "main_window.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QToolBar>

#include "stability/lobe_diagram.h"

namespace mx::gui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      chart_(new widgets::LobeChartView(this)),
      tool_list_(new QListWidget(this)),
      status_label_(new QLabel(this)),
      progress_(new QProgressBar(this)),
      engine_(new EngineRunner(this)) {
  setWindowTitle("MillExpert");
  setWindowIcon(QIcon(":/icons/millexpert.svg"));
  setCentralWidget(chart_);
  auto* dock = new QDockWidget(tr("Tools"), this);
  dock->setObjectName("toolsDock");
  dock->setWidget(tool_list_);
  tool_list_->setToolTip(tr("Tools of the project: teeth, diameter and modes"));
  addDockWidget(Qt::LeftDockWidgetArea, dock);
  progress_->setRange(0, 0);
  progress_->setMaximumWidth(160);
  progress_->setVisible(false);
  statusBar()->addWidget(status_label_, 1);
  statusBar()->addPermanentWidget(progress_);
  buildMenus();
  connect(engine_, &EngineRunner::lobesReady, this, &MainWindow::onLobesReady);
  connect(engine_, &EngineRunner::busyChanged, progress_, &QProgressBar::setVisible);
  resize(1280, 800);
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QToolBar* toolbar = addToolBar(tr("Main"));
  toolbar->setObjectName("mainToolbar");
  QAction* open = file->addAction(tr("&Open project..."), this, &MainWindow::onOpen);
  open->setShortcut(QKeySequence::Open);
  open->setToolTip(tr("Open a MillExpert project (.mxproj)"));
  toolbar->addAction(open);
  QAction* exportChart = file->addAction(tr("&Export chart..."), this, &MainWindow::onExportChart);
  exportChart->setShortcut(QKeySequence(tr("Ctrl+E")));
  exportChart->setToolTip(tr("Save the lobe chart as PNG or PDF"));
  toolbar->addAction(exportChart);
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);
}

void MainWindow::showError(const QString& title, const QString& message) {
  status_label_->setText(title + ": " + message);
  if (!quiet_) QMessageBox::critical(this, title, message);
}

bool MainWindow::openProject(const QString& path) {
  try {
    app::Project project = app::loadProject(path);
    project_ = std::move(project);
  } catch (const app::ProjectError& e) {
    showError(tr("Cannot open project"), QString::fromStdString(e.what()));
    return false;
  }
  project_path_ = path;
  setWindowTitle(QString("MillExpert \u2014 %1 [%2]").arg(project_->name, QFileInfo(path).fileName()));
  tool_list_->clear();
  for (int i = 0; i < static_cast<int>(project_->tools.size()); ++i) {
    const app::ToolSpec& t = project_->tools[static_cast<size_t>(i)];
    auto* item = new QListWidgetItem(QString("%1: %2 teeth, D = %3 mm, %4 + %5 modes")
                                         .arg(t.id)
                                         .arg(t.teeth)
                                         .arg(t.diameter_mm)
                                         .arg(t.modes_x.size())
                                         .arg(t.modes_y.size()));
    item->setForeground(widgets::LobeChartView::toolColor(i));
    tool_list_->addItem(item);
  }
  recomputeLobes();
  return true;
}

void MainWindow::recomputeLobes() {
  LobeJobInput input;
  double from = 1000.0, to = 20000.0, step = 10.0;  // fine grid for smooth lobe peaks
  if (project_->expert) {
    input.delta_per_s = project_->expert->delta_per_s;
    input.alpha = project_->expert->alpha;
    if (project_->expert->grid) {
      from = project_->expert->grid->speed_from_rpm;
      to = project_->expert->grid->speed_to_rpm;
      step = std::min(step, project_->expert->grid->speed_step_rpm);
    }
  }
  input.speeds_rev_per_s = SpeedGrid{rpmToRevPerS(from), rpmToRevPerS(to), rpmToRevPerS(step)}.values();
  try {
    for (const app::ToolSpec& t : project_->tools) input.tools.push_back(project_->setupFor(t.id));
  } catch (const app::ProjectError& e) {
    showError(tr("Cannot compute lobes"), QString::fromStdString(e.what()));
    return;
  }
  status_label_->setText(tr("Computing stability lobes of %1 tool(s)...").arg(input.tools.size()));
  engine_->submitLobes(std::move(input));
}

void MainWindow::onLobesReady(const LobeJobResult& result) {
  if (!result.error.isEmpty()) {
    showError(tr("Lobe computation failed"), result.error);
    return;
  }
  const double delta = project_->expert ? project_->expert->delta_per_s : 0.0;
  const double alpha = project_->expert ? project_->expert->alpha : 1.0;
  chart_->setSeries(result.series, delta, alpha);
  status_label_->setText(tr("Lobes of %1 tool(s): zeroth-order approximation, \u03b4 = %2 1/s, \u03b1 = %3")
                             .arg(result.series.size())
                             .arg(delta)
                             .arg(alpha));
  emit lobesShown();
}

void MainWindow::onOpen() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Open project"), QFileInfo(project_path_).path(),
                                                    tr("MillExpert projects (*.mxproj);;All files (*)"));
  if (!path.isEmpty()) openProject(path);
}

void MainWindow::onExportChart() {
  const QString path =
      QFileDialog::getSaveFileName(this, tr("Export chart"), "lobes.png", tr("PNG image (*.png);;PDF (*.pdf)"));
  if (!path.isEmpty() && !chart_->saveImage(path)) showError(tr("Export failed"), path);
}

}  // namespace mx::gui
