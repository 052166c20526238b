#include "main_window.h"

#include <QCloseEvent>
#include <QFile>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <cmath>
#include <limits>
#include <utility>

#include "control_feature.h"
#include "document/lobe_inputs.h"
#include "expert_runner.h"
#include "machine_operation_panel.h"
#include "machining_feature.h"
#include "pareto_runner.h"
#include "pareto_weights_panel.h"
#include "simulation_runner.h"
#include "simulation_view.h"
#include "stability/lobe_diagram.h"
#include "supervisor_feature.h"
#include "tool_library_editor.h"
#include "weights_panel.h"

namespace mx::gui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      chart_(new widgets::LobeChartView(this)),
      readout_(new widgets::OperatingPointReadout(this)),
      engine_(new EngineRunner(this)),
      tool_combo_(new QComboBox(this)),
      method_combo_(new QComboBox(this)),
      feed_spin_(new QDoubleSpinBox(this)),
      status_point_(new QLabel(this)),
      status_engine_(new QLabel(this)),
      progress_(new QProgressBar(this)),
      cancel_button_(new QToolButton(this)) {
  setObjectName("MillExpertMainWindow");
  setWindowIcon(QIcon(":/icons/millexpert.svg"));
  setCentralWidget(chart_);
  sim_runner_ = new SimulationRunner(engine_->pool(), this);
  readout_->setUnits(&units_);
  buildDocks();
  buildExpertDocks();
  buildParetoDocks();
  addFeature(new ControlFeature(this, doc_, engine_->pool()));
  addFeature(new MachiningFeature(this, doc_, engine_->pool()));
  addFeature(new SupervisorFeature(this, doc_, engine_->pool()));
  buildActions();

  progress_->setRange(0, 100);
  progress_->setMaximumWidth(180);
  progress_->setVisible(false);
  cancel_button_->setText(tr("Cancel"));
  cancel_button_->setToolTip(tr("Cancel the running computation"));
  cancel_button_->setVisible(false);
  statusBar()->addWidget(status_point_, 1);
  statusBar()->addPermanentWidget(status_engine_);
  statusBar()->addPermanentWidget(progress_);
  statusBar()->addPermanentWidget(cancel_button_);
  status_engine_->setText(tr("Engine idle"));

  recompute_timer_.setSingleShot(true);
  recompute_timer_.setInterval(120);
  connect(&recompute_timer_, &QTimer::timeout, this, &MainWindow::recomputeEngine);
  connect(&doc_, &app::ProjectDocument::changed, this, &MainWindow::onProjectChanged);
  connect(&doc_, &app::ProjectDocument::pointChanged, this, &MainWindow::onPointChanged);
  connect(&doc_, &app::ProjectDocument::dirtyChanged, this, &MainWindow::updateTitle);
  connect(&doc_, &app::ProjectDocument::filePathChanged, this, &MainWindow::updateTitle);
  connect(engine_, &EngineRunner::lobesReady, this, &MainWindow::onLobesReady);
  connect(engine_, &EngineRunner::lobeProgress, this, [this](double f) { progress_->setValue(qRound(100 * f)); });
  connect(engine_, &EngineRunner::busyChanged, this, [this](bool busy) {
    progress_->setVisible(busy);
    cancel_button_->setVisible(busy);
    progress_->setValue(0);
    status_engine_->setText(busy ? tr("Engine: computing lobes...") : tr("Engine idle"));
  });
  connect(cancel_button_, &QToolButton::clicked, this, [this] {
    engine_->cancelAll();
    sim_runner_->cancel();
  });
  connect(chart_, &widgets::LobeChartView::pointDragged, this, &MainWindow::onPointDragged);
  connect(chart_, &widgets::LobeChartView::pointReleased, this, &MainWindow::onPointReleased);
  connect(sim_runner_, &SimulationRunner::chunkReady, this, [this](quint64 g, const SimulationChunkData& chunk) {
    if (g == sim_generation_) sim_view_->appendChunk(chunk);
  });
  connect(sim_runner_, &SimulationRunner::finished, this, &MainWindow::onSimulationFinished);
  connect(sim_runner_, &SimulationRunner::failed, this, [this](quint64 g, const QString& message) {
    if (g == sim_generation_) sim_view_->setStatus(tr("Simulation failed: %1").arg(message));
  });
  connect(sim_view_, &widgets::SimulationView::moveToSpeedRequested, this, [this](double rpm) {
    app::PickedPoint p = doc_.point();
    p.speed_rpm = rpm;
    doc_.setPoint(p);
    startSimulation();
  });
  resize(1600, 950);
  updateTitle();
  onProjectChanged(app::kAllSections);
}

MainWindow::~MainWindow() {
  for (WindowFeature* feature : features_) feature->stop();
  sim_runner_->cancel();
  engine_->cancelAll();
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

void MainWindow::setMethod(LobeMethod method) {
  method_combo_->setCurrentIndex(method == LobeMethod::ZeroOrder ? 0 : 1);
}

// The project changed (edit, undo, redo, load): each feature whose inputs are among `changes`
// recomputes (featuresToRecompute); the others keep their results.
void MainWindow::onProjectChanged(app::ProjectChanges changes) {
  const Features f = featuresToRecompute(changes);
  const app::Project& p = doc_.project();
  if (f & Feature::Editors) refreshEditors();
  if (f & Feature::ParetoStudy) {
    pareto_timer_.start();
  } else if ((f & Feature::ParetoChoice) && pareto_->study()) {
    pareto_weights_->setWeights(projectParetoWeightsOf(p));
    showParetoChoice(pareto_weights_->weights());
  }
  if (f & Feature::FiredRules) updateFiredRules();
  for (WindowFeature* feature : features_) feature->projectChanged(p, f);
  if (f & Feature::Simulation) startSimulation();
  // Lobes and the expert session wait for the edits to pause (one recomputation per burst).
  pending_engine_ |= f & (Feature::Lobes | Feature::ExpertSession);
  if (pending_engine_) {
    recompute_timer_.start();
  } else if (f & Feature::ExpertRerank) {
    // Rule 4 again from the cached session, and Rules 5-6 for q**: no lobes or grids.
    const CostWeights w = projectWeightsOf(p);
    weights_panel_->setWeights(w);
    if (expert_->session()) {
      rerank(w);
      expert_->refine(w);
    }
  }
}

// The tool table, the machine and operation panel, and the tool choices of the toolbar and menu.
void MainWindow::refreshEditors() {
  const app::Project& p = doc_.project();
  if (tool_editor_) tool_editor_->setProject(p);
  if (machine_panel_) machine_panel_->setProject(p);
  const QString keep = active_tool_;
  tool_combo_->blockSignals(true);
  tool_combo_->clear();
  for (const app::ToolSpec& t : p.tools) tool_combo_->addItem(t.id);
  const int index = tool_combo_->findText(keep);
  tool_combo_->setCurrentIndex(index >= 0 ? index : 0);
  tool_combo_->blockSignals(false);
  active_tool_ = tool_combo_->currentText();
  if (tools_menu_) {
    tools_menu_->clear();
    for (const app::ToolSpec& t : p.tools) {
      QAction* a = tools_menu_->addAction(t.id);
      a->setCheckable(true);
      a->setChecked(chart_->isToolVisible(t.id));
      connect(a, &QAction::toggled, this, [this, id = t.id](bool on) { chart_->setToolVisible(id, on); });
    }
  }
}

void MainWindow::recomputeEngine() {
  const Features pending = std::exchange(pending_engine_, {});
  if (pending & Feature::Lobes) recomputeLobes();
  if (pending & Feature::ExpertSession) rebuildExpert();
}

void MainWindow::recomputeLobes() {
  const app::Project& p = doc_.project();
  LobeJobInput input;
  input.method = method_;
  app::LobeInputs lobes = app::lobeInputsFrom(p, 10.0);  // the ZOA is cheap on a fine grid
  input.delta_per_s = lobes.delta_per_s;
  input.alpha = lobes.alpha;
  // The SDM envelope uses 200 speeds.
  if (method_ == LobeMethod::SemiDiscretization)
    lobes.step_rpm = std::max((lobes.to_rpm - lobes.from_rpm) / 199.0, 1.0);
  input.speeds_rev_per_s = lobes.grid().values();
  try {
    for (const app::ToolSpec& t : p.tools) input.tools.push_back(p.setupFor(t.id));
  } catch (const app::ProjectError& e) {
    chart_->clear();
    snapshot_.reset();
    evaluator_ = PointEvaluator();
    status_engine_->setText(tr("Lobes unavailable: %1").arg(QString::fromStdString(e.what())));
    return;
  }
  if (input.tools.empty()) {
    chart_->clear();
    return;
  }
  engine_->submitLobes(std::move(input));
}

void MainWindow::onLobesReady(const LobeJobResult& result) {
  if (result.cancelled) {
    statusBar()->showMessage(tr("Lobe computation cancelled"), 5000);
    return;
  }
  if (!result.error.isEmpty()) {
    showError(tr("Lobe computation failed"), result.error);
    return;
  }
  snapshot_ = result.snapshot;
  const app::Project& p = doc_.project();
  evaluator_ = PointEvaluator(snapshot_, p.machine ? p.machine->spindle_power_W : 0.0);
  chart_->setSeries(snapshot_->series(), snapshot_->delta_per_s, snapshot_->alpha);
  const int tool = std::max(0, evaluator_.toolIndex(active_tool_));
  chart_->setActiveTool(tool);
  // Snap grid (Shift): the expert grid's speed step, and depth steps of b_min / depth_divisions.
  double b_min = std::numeric_limits<double>::infinity();
  for (double b : snapshot_->tools[static_cast<size_t>(tool)].margined.envelope_depth_m) b_min = std::min(b_min, b);
  const int divisions = p.expert && p.expert->grid ? p.expert->grid->depth_divisions : 10;
  chart_->setSnapGrid(p.expert && p.expert->grid ? p.expert->grid->speed_step_rpm : 100.0,
                      std::isfinite(b_min) ? snapshot_->alpha * b_min * 1e3 / divisions : 0.0);
  if (doc_.point().speed_rpm <= 0.0) {
    // First lobes of this project: start in the middle of the range at half the limit there.
    const auto& speeds = snapshot_->tools[static_cast<size_t>(tool)].margined.speed_rev_per_s;
    app::PickedPoint start;
    start.speed_rpm = std::round(revPerSToRpm(0.5 * (speeds.front() + speeds.back())) / 100.0) * 100.0;
    const widgets::PointReadout r = evaluator_.evaluate(tool, start.speed_rpm, 0.0, 0.1);
    start.depth_mm = std::isfinite(r.blim_mm) ? 0.5 * r.blim_mm : 1.0;
    start.feed_mm_per_tooth = p.operation ? 0.5 * p.operation->max_feed_per_tooth_mm : 0.1;
    doc_.initPoint(start);
    startSimulation();
  } else {
    onPointChanged(doc_.point());
  }
  updatePowerLimit();
  status_engine_->setText(
      tr("Lobes: %1, %2 tool(s)")
          .arg(snapshot_->method == LobeMethod::ZeroOrder ? tr("zeroth-order") : tr("semi-discretization"))
          .arg(snapshot_->tools.size()));
  updateExpertOverlays();  // the chart was rebuilt: markers and heat map again
  emit lobesShown();
}

void MainWindow::updatePowerLimit() {
  const int tool = evaluator_.toolIndex(active_tool_);
  const double feed = doc_.point().feed_mm_per_tooth;
  power_limit_feed_ = feed;
  const app::Project& p = doc_.project();
  const QVector<double> limit = evaluator_.powerLimitMm(tool, feed);
  chart_->setPowerLimit(
      limit, p.machine
                 ? tr("power limit %1 W at s_t = %2 mm/tooth").arg(p.machine->spindle_power_W).arg(feed, 0, 'f', 3)
                 : QString());
}

void MainWindow::onPointChanged(const app::PickedPoint& point) {
  if (point.feed_mm_per_tooth != power_limit_feed_) updatePowerLimit();  // the curve depends on s_t
  const int tool = evaluator_.toolIndex(active_tool_);
  const widgets::PointReadout r = evaluator_.evaluate(tool, point.speed_rpm, point.depth_mm, point.feed_mm_per_tooth);
  readout_->setReadout(r);
  widgets::PointVerdict verdict = widgets::PointVerdict::Unknown;
  if (r.valid)
    verdict = !r.stable      ? widgets::PointVerdict::Unstable
              : !r.powerOk() ? widgets::PointVerdict::PowerExceeded
                             : widgets::PointVerdict::Stable;
  chart_->setOperatingPoint(point.speed_rpm, point.depth_mm, verdict);
  updateFiredRules();
  updateMonitoring();
  feed_spin_->blockSignals(true);
  feed_spin_->setValue(units_.fromMm(point.feed_mm_per_tooth));
  feed_spin_->blockSignals(false);
  status_point_->setText(tr("Point: %1 rpm, b = %2 mm, s_t = %3 mm/tooth \u2014 %4")
                             .arg(point.speed_rpm, 0, 'f', 0)
                             .arg(point.depth_mm, 0, 'f', 3)
                             .arg(point.feed_mm_per_tooth, 0, 'f', 3)
                             .arg(readout_->text("verdict")));
}

void MainWindow::onPointDragged(double speed_rpm, double depth_mm) {
  app::PickedPoint p = doc_.point();
  p.speed_rpm = speed_rpm;
  p.depth_mm = depth_mm;
  doc_.setPoint(p, drag_id_);
}

void MainWindow::onPointReleased(double speed_rpm, double depth_mm) {
  onPointDragged(speed_rpm, depth_mm);
  ++drag_id_;
  startSimulation();
}

void MainWindow::startSimulation() {
  const app::Project& p = doc_.project();
  const app::PickedPoint& pt = doc_.point();
  if (active_tool_.isEmpty() || pt.speed_rpm <= 0.0 || pt.feed_mm_per_tooth <= 0.0) return;
  try {
    const MillingSetup setup = p.setupFor(active_tool_);
    SimulationOptions options;
    options.revolutions = 60;
    const double power = p.machine ? p.machine->spindle_power_W : 0.0;
    const double max_speed = p.machine && p.machine->max_spindle_rpm ? rpmToRevPerS(*p.machine->max_spindle_rpm)
                                                                     : std::numeric_limits<double>::infinity();
    const OperatingPoint op{rpmToRevPerS(pt.speed_rpm), pt.depth_mm * 1e-3, pt.feed_mm_per_tooth * 1e-3};
    sim_generation_ = sim_runner_->submit(setup, op, options, power, max_speed);
    sim_view_->beginRun(power, setup.teeth, op.spindle_rev_per_s * setup.teeth);
  } catch (const std::exception& e) {
    sim_view_->setStatus(tr("Cannot simulate: %1").arg(e.what()));
  }
}

void MainWindow::onSimulationFinished(quint64 generation, const SimulationSummary& summary) {
  if (generation != sim_generation_) return;
  sim_view_->setSummary(summary);
  updateMonitoring(&summary);
  emit simulationFinished();
}

void MainWindow::setActiveTool(const QString& id) {
  if (id.isEmpty() || id == active_tool_) return;
  active_tool_ = id;
  const int index = tool_combo_->findText(id);
  if (index >= 0 && tool_combo_->currentIndex() != index) tool_combo_->setCurrentIndex(index);
  chart_->setActiveTool(evaluator_.toolIndex(id));
  updatePowerLimit();
  onPointChanged(doc_.point());
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
