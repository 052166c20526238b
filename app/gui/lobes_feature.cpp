#include "lobes_feature.h"

#include <QDockWidget>
#include <QFileDialog>
#include <QFormLayout>
#include <QStatusBar>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "document/frf_paths.h"
#include "document/lobe_inputs.h"
#include "feature_dock.h"
#include "services/measured_dynamics.h"
#include "stability/lobe_diagram.h"
#include "stability_model_text.h"

namespace mx::gui {

LobesFeature::LobesFeature(QMainWindow* window, FeatureContext& context, EngineRunner* engine)
    : WindowFeature(window),
      context_(context),
      engine_(engine),
      chart_(new widgets::LobeChartView(window)),
      readout_(new widgets::OperatingPointReadout(window)),
      tool_combo_(new QComboBox(window)),
      method_combo_(new QComboBox(window)),
      method_advice_(new QLabel(window)),
      feed_spin_(new QDoubleSpinBox(window)),
      status_point_(new QLabel(window)),
      status_engine_(new QLabel(window)),
      progress_(new QProgressBar(window)),
      cancel_button_(new QToolButton(window)),
      evaluator_(std::make_shared<PointEvaluator>()),
      point_runner_(new PointRunner(this)) {
  setObjectName("lobesFeature");
  window->setCentralWidget(chart_);
  readout_->setUnits(context_.units());
  window->addDockWidget(Qt::RightDockWidgetArea, makeFeatureDock(window, tr("Operating point"), "pointDock",
                                                                 buildPointPanel(), DockContent::Scrolling));
  buildStatusBar(window);
  recompute_timer_.setSingleShot(true);
  recompute_timer_.setInterval(120);
  connectSignals();
  showMethodAdvice();
}

// The point panel: active tool, feed per tooth, readouts.
QWidget* LobesFeature::buildPointPanel() {
  auto* panel = new QWidget;
  auto* layout = new QVBoxLayout(panel);
  auto* form = new QFormLayout;
  tool_combo_->setToolTip(tr("The tool whose lobes, power limit and readouts are shown"));
  method_combo_->addItems({tr("Zeroth-order approximation"), tr("Semi-discretization")});
  feed_spin_->setObjectName("pointFeedSpin");
  feed_spin_->setRange(0.001, 5.0);
  feed_spin_->setDecimals(4);
  feed_spin_->setSingleStep(0.01);
  feed_spin_->setSuffix(" mm/tooth");
  feed_spin_->setToolTip(tr("Feed per tooth of the operating point (power, MRR and simulation)"));
  form->addRow(tr("Tool:"), tool_combo_);
  form->addRow(tr("Feed per tooth:"), feed_spin_);
  layout->addLayout(form);
  method_advice_->setWordWrap(true);
  method_advice_->setStyleSheet("color: #a05a00;");
  method_advice_->setToolTip(
      tr("The ZOA ignores the helix and pitch differences and averages the cut; the SDM "
         "models pitch and helix (switch the method in the toolbar)"));
  method_advice_->hide();
  layout->addWidget(method_advice_);
  layout->addWidget(readout_);
  panel->setMinimumWidth(300);
  return panel;
}

void LobesFeature::buildStatusBar(QMainWindow* window) {
  progress_->setRange(0, 100);
  progress_->setMaximumWidth(180);
  progress_->setVisible(false);
  cancel_button_->setText(tr("Cancel"));
  cancel_button_->setToolTip(tr("Cancel the running computation"));
  cancel_button_->setVisible(false);
  window->statusBar()->addWidget(status_point_, 1);
  window->statusBar()->addPermanentWidget(status_engine_);
  window->statusBar()->addPermanentWidget(progress_);
  window->statusBar()->addPermanentWidget(cancel_button_);
  status_engine_->setText(tr("Engine idle"));
}

void LobesFeature::connectSignals() {
  connect(&recompute_timer_, &QTimer::timeout, this, &LobesFeature::recompute);
  connect(engine_, &EngineRunner::lobesReady, this, &LobesFeature::onLobesReady);
  connect(point_runner_, &PointRunner::evaluated, this, &LobesFeature::onPointEvaluated);
  connect(&context_, &FeatureContext::simulationStateChanged, this,
          [this] { readout_->setSimulation(context_.simulationCheck()); });
  connect(engine_, &EngineRunner::lobeProgress, this, [this](double f) { progress_->setValue(qRound(100 * f)); });
  connect(engine_, &EngineRunner::busyChanged, this, [this](bool busy) {
    progress_->setVisible(busy);
    cancel_button_->setVisible(busy);
    progress_->setValue(0);
    status_engine_->setText(busy ? tr("Engine: computing lobes...") : tr("Engine idle"));
  });
  connect(cancel_button_, &QToolButton::clicked, this, &LobesFeature::cancelRequested);
  connect(chart_, &widgets::LobeChartView::pointDragged, this, &LobesFeature::onPointDragged);
  connect(chart_, &widgets::LobeChartView::pointReleased, this, [this](double speed_rpm, double depth_mm) {
    onPointDragged(speed_rpm, depth_mm);
    ++drag_id_;
    emit context_.simulationRequested();
  });
  connect(&context_.document(), &app::ProjectDocument::pointChanged, this, &LobesFeature::showPoint);
  connect(&context_, &FeatureContext::activeToolChanged, this, &LobesFeature::showActiveTool);
  connect(chart_, &widgets::LobeChartView::activeToolRequested, this, [this](int index) {
    if (snapshot_ && index < static_cast<int>(snapshot_->tools.size()))
      context_.setActiveTool(QString::fromStdString(snapshot_->tools[static_cast<size_t>(index)].setup.tool_id));
  });
  connect(chart_, &widgets::LobeChartView::toolVisibilityChanged, this, [this](const QString& id, bool visible) {
    if (!tools_menu_) return;
    for (QAction* a : tools_menu_->actions())
      if (a->text() == id) a->setChecked(visible);
  });
  connect(tool_combo_, &QComboBox::currentTextChanged, &context_, &FeatureContext::setActiveTool);
  connect(method_combo_, &QComboBox::currentIndexChanged, this, [this](int index) {
    method_ = index == 0 ? LobeMethod::ZeroOrder : LobeMethod::SemiDiscretization;
    showMethodAdvice();
    recompute();
  });
  connect(feed_spin_, &QDoubleSpinBox::editingFinished, this, [this] {
    app::PickedPoint p = context_.point();
    p.feed_mm_per_tooth = context_.units()->shop().toBase(widgets::Quantity::ChipLoad, feed_spin_->value());
    emit pointRequested(p, 0);
  });
  connect(this, &LobesFeature::lobesShown, &context_, &FeatureContext::lobesShown);
  connect(context_.units(), &widgets::DisplayUnits::changed, this, [this] {
    const widgets::DisplayUnits& units = *context_.units();
    feed_spin_->setSuffix(" " + units.shop().symbol(widgets::Quantity::ChipLoad));
    feed_spin_->setDecimals(units.shop().decimals(widgets::Quantity::ChipLoad));
    feed_spin_->setRange(units.shop().fromBase(widgets::Quantity::ChipLoad, 0.001),
                         units.shop().fromBase(widgets::Quantity::ChipLoad, 5.0));
    chart_->setLengthUnit(units.fromMm(1.0), units.lengthSuffix());
    power_limit_feed_ = -1.0;  // the power-limit curve's label is in shop units: redrawn with the readout
    showPoint(context_.point());
    showStatusPoint();
  });
}

void LobesFeature::addFileActions(QMenu* file, QToolBar* toolbar) {
  QAction* a = file->addAction(tr("&Export chart..."));
  a->setShortcut(QKeySequence(tr("Ctrl+E")));
  a->setToolTip(tr("Save the lobe chart as PNG, SVG or PDF"));
  a->setStatusTip(a->toolTip());
  connect(a, &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getSaveFileName(chart_, tr("Export chart"), "lobes.png",
                                                      tr("PNG image (*.png);;SVG drawing (*.svg);;PDF (*.pdf)"));
    if (!path.isEmpty() && !chart_->saveImage(path)) emit errorRaised(tr("Export failed"), path);
  });
  toolbar->addAction(a);
}

void LobesFeature::addViewActions(QMenu* view, QToolBar* toolbar) {
  QAction* reset = view->addAction(tr("&Reset chart view"));
  reset->setShortcut(QKeySequence(tr("Ctrl+0")));
  reset->setToolTip(tr("Show the whole speed range"));
  reset->setStatusTip(reset->toolTip());
  connect(reset, &QAction::triggered, chart_, &widgets::LobeChartView::resetView);
  toolbar->addAction(reset);
  tools_menu_ = view->addMenu(tr("&Tools on the chart"));
  tools_menu_->setToolTip(tr("Choose which tools' lobes the chart shows"));
  refreshToolChoices(context_.project());
  toolbar->addWidget(method_combo_);
}

void LobesFeature::stop() {
  engine_->cancelAll();
}

void LobesFeature::setMethod(LobeMethod method) {
  method_combo_->setCurrentIndex(method == LobeMethod::ZeroOrder ? 0 : 1);
}

// The tool choices follow the tool library; lobes wait for the edits to pause.
void LobesFeature::projectChanged(const app::Project& project, Features recompute) {
  if (recompute & Feature::Editors) {
    refreshToolChoices(project);
    showMethodAdvice();
  }
  if (recompute & Feature::Lobes) {
    engine_->dropPending();  // lobes of the project before this change would show as its lobes
    recompute_timer_.start();
  }
  if (snapshot_ && (recompute & (Feature::ExpertSession | Feature::Editors))) {  // a tool's or the breakage limit
    updateForceLimits();
    showPoint(context_.point());
  }
}

// F_allow of each snapshot tool from the current project (a removed tool: no limit until new lobes).
void LobesFeature::updateForceLimits() {
  const app::Project& p = context_.project();
  std::vector<double> limits;
  for (const ToolLobes& t : snapshot_->tools) {
    const app::ToolSpec* spec = p.findTool(QString::fromStdString(t.setup.tool_id));
    limits.push_back(spec ? p.toolForceLimitN(*spec) : std::numeric_limits<double>::infinity());
  }
  auto evaluator = std::make_shared<PointEvaluator>(*evaluator_);
  evaluator->setForceLimits(std::move(limits));
  evaluator_ = std::move(evaluator);
  context_.setEvaluator(evaluator_);
}

// The toolbar's tool choice and View > Tools on the chart; the active tool stays when it still exists.
void LobesFeature::refreshToolChoices(const app::Project& project) {
  const QString keep = context_.activeTool();
  tool_combo_->blockSignals(true);
  tool_combo_->clear();
  for (const app::ToolSpec& t : project.tools) tool_combo_->addItem(t.id);
  const int index = tool_combo_->findText(keep);
  tool_combo_->setCurrentIndex(index >= 0 ? index : 0);
  tool_combo_->blockSignals(false);
  context_.setActiveTool(tool_combo_->currentText());
  if (!tools_menu_) return;
  tools_menu_->clear();
  for (const app::ToolSpec& t : project.tools) {
    QAction* a = tools_menu_->addAction(t.id);
    a->setCheckable(true);
    a->setChecked(chart_->isToolVisible(t.id));
    connect(a, &QAction::toggled, this, [this, id = t.id](bool on) { chart_->setToolVisible(id, on); });
  }
}

void LobesFeature::recompute() {
  recompute_timer_.stop();
  const app::Project& p = context_.project();
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
    // The FRF files are read on the engine thread, from a snapshot that names them by absolute path.
    std::shared_ptr<const app::Project> frf_snapshot;
    for (const app::ToolSpec& t : p.tools) {
      input.tools.push_back(p.setupFor(t.id));
      if (!t.hasFrf()) {
        input.frfs.emplace_back();
        continue;
      }
      if (!frf_snapshot) frf_snapshot = std::make_shared<const app::Project>(app::withAbsoluteFrfPaths(p));
      input.frfs.emplace_back(LobeFrfSource{frf_snapshot, app::defaultDynamics(t) == DynamicsSource::Modal});
    }
  } catch (const app::ProjectError& e) {
    chart_->clear();
    snapshot_.reset();
    evaluator_ = std::make_shared<PointEvaluator>();
    context_.setEvaluator(evaluator_);
    status_engine_->setText(tr("Lobes unavailable: %1").arg(QString::fromStdString(e.what())));
    return;
  }
  if (input.tools.empty()) {
    showNoTools();
    return;
  }
  engine_->submitLobes(std::move(input));
}

// A project without a tool (File > New, the last tool removed): no lobes and nothing to read out, not
// the previous project's readouts; the start page covers the chart.
void LobesFeature::showNoTools() {
  chart_->clear();
  snapshot_.reset();
  evaluator_ = std::make_shared<PointEvaluator>();
  context_.setEvaluator(evaluator_);
  widgets::PointReadout none;
  none.message = tr("No tool: add one in the tool library");
  readout_->setReadout(none);
  context_.setReadout(none);
  status_engine_->setText(tr("Lobes: no tool"));
  status_point_->setText(none.message);
}

void LobesFeature::onLobesReady(const LobeJobResult& result) {
  if (result.cancelled) {
    emit statusMessage(tr("Lobe computation cancelled"), 5000);
    return;
  }
  if (!result.error.isEmpty()) {
    emit errorRaised(tr("Lobe computation failed"), result.error);
    return;
  }
  snapshot_ = result.snapshot;
  const app::Project& p = context_.project();
  evaluator_ =
      std::make_shared<PointEvaluator>(snapshot_, p.machine ? app::spindlePowerOf(*p.machine) : SpindlePowerCurve{});
  updateForceLimits();
  chart_->setSeries(snapshot_->series(), snapshot_->delta_per_s, snapshot_->alpha);
  const int tool = std::max(0, evaluator_->toolIndex(context_.activeTool()));
  chart_->setActiveTool(tool);
  showModelLabel();
  setSnapGrid(tool);
  if (context_.point().speed_rpm <= 0.0)
    pickInitialPoint(tool);
  else
    showPoint(context_.point());
  if (!snapshot_->warnings.isEmpty())
    emit statusMessage(tr("Measured-FRF lobes left out: %1").arg(snapshot_->warnings.join("; ")), 15000);
  status_engine_->setText(
      tr("Lobes: %1, %2 tool(s)")
          .arg(snapshot_->method == LobeMethod::ZeroOrder ? tr("zeroth-order") : tr("semi-discretization"))
          .arg(snapshot_->tools.size()));
  emit lobesShown();
}

// Snap grid (Shift): the expert grid's speeds (from its first speed, in its steps), and depth steps of
// b_min / depth_divisions.
void LobesFeature::setSnapGrid(int tool) {
  const app::Project& p = context_.project();
  double b_min = std::numeric_limits<double>::infinity();
  for (double b : snapshot_->tools[static_cast<size_t>(tool)].margined.envelope_depth_m) b_min = std::min(b_min, b);
  const bool grid = p.expert && p.expert->grid;
  const int divisions = grid ? p.expert->grid->depth_divisions : 10;
  chart_->setSnapGrid(grid ? p.expert->grid->speed_from_rpm : 0.0, grid ? p.expert->grid->speed_step_rpm : 100.0,
                      std::isfinite(b_min) ? snapshot_->alpha * b_min * 1e3 / divisions : 0.0);
}

namespace {

constexpr double kInitialStabilityShare = 0.5;  // of b_lim: well inside the lobes
constexpr double kInitialPowerShare = 0.8;      // of the depth at the power limit
constexpr double kInitialRateTolerance = 0.02;  // removal rates this close count as equal

// The lowest lobe speed of the largest removal rate N b among the speeds the machine turns (up to
// `max_rpm`), b being half the stability limit and at most 80 % of the power-limited depth where that
// is known (`power_mm`, one per speed): within 2 % of the largest rate the deepest cut wins, rather than
// a pocket's top. nullopt when no speed has a finite limit.
std::optional<app::PickedPoint> initialCut(const PointEvaluator& evaluator, int tool, const std::vector<double>& speeds,
                                           double max_rpm, const QVector<double>* power_mm) {
  std::vector<app::PickedPoint> cuts;
  double best_rate = 0.0;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double rpm = std::round(revPerSToRpm(speeds[i]));
    if (rpm > max_rpm) break;
    double depth = kInitialStabilityShare * evaluator.depthLimitMm(tool, rpm);
    if (power_mm) depth = std::min(depth, kInitialPowerShare * power_mm->value(static_cast<qsizetype>(i)));
    if (!std::isfinite(depth) || !(depth > 0.0)) continue;
    cuts.push_back({rpm, depth, 0.0});
    best_rate = std::max(best_rate, rpm * depth);
  }
  for (const app::PickedPoint& cut : cuts)
    if (cut.speed_rpm * cut.depth_mm >= (1.0 - kInitialRateTolerance) * best_rate) return cut;
  return std::nullopt;
}

double maxSpindleRpm(const app::Project& p) {
  return p.machine && p.machine->max_spindle_rpm ? *p.machine->max_spindle_rpm
                                                 : std::numeric_limits<double>::infinity();
}

}  // namespace

// The first lobes of a project without a stored operating point (q* replaces it when the expert ranking
// arrives): the cut of initialCut at half the feed limit, until the power-limit curve is known
// (lowerInitialPoint); the middle of the range at 1 mm when the lobes give no limit. The simulation
// follows the point once it settles (its re-run after a pause), so that it never runs this first guess.
void LobesFeature::pickInitialPoint(int tool) {
  const app::Project& p = context_.project();
  const auto& speeds = snapshot_->tools[static_cast<size_t>(tool)].margined.speed_rev_per_s;
  app::PickedPoint start;
  start.speed_rpm = std::round(revPerSToRpm(0.5 * (speeds.front() + speeds.back())) / 100.0) * 100.0;
  start.depth_mm = 1.0;
  if (const auto cut = initialCut(*evaluator_, tool, speeds, maxSpindleRpm(p), nullptr)) start = *cut;
  start.feed_mm_per_tooth = p.operation ? 0.5 * p.operation->max_feed_per_tooth_mm : 0.1;
  initial_point_ = start;
  context_.setDefaultPoint(start);
  emit initialPointRequested(start);
}

// The power-limit curve of the first point's feed is known: the cut is chosen again with it, so that
// the point starts below the power limit, at the speed where the power allows the best cut.
void LobesFeature::lowerInitialPoint(const PointJobResult& result) {
  if (!initial_point_) return;  // onPointEvaluated passes only the current lobes' answers with a curve
  if (result.point.feed_mm_per_tooth != initial_point_->feed_mm_per_tooth) return;  // a curve of another feed
  const std::optional<app::PickedPoint> initial = std::exchange(initial_point_, std::nullopt);
  if (!(*initial == context_.point()) || result.power_limit_mm->isEmpty()) return;  // moved, or no power limit
  const auto& speeds = snapshot_->tools[static_cast<size_t>(result.tool)].margined.speed_rev_per_s;
  if (result.power_limit_mm->size() != static_cast<qsizetype>(speeds.size())) return;
  std::optional<app::PickedPoint> cut =
      initialCut(*evaluator_, result.tool, speeds, maxSpindleRpm(context_.project()), &*result.power_limit_mm);
  if (!cut) return;
  cut->feed_mm_per_tooth = initial->feed_mm_per_tooth;
  if (*cut == *initial) return;
  context_.setDefaultPoint(*cut);
  emit initialPointRequested(*cut);
}

namespace {
// "power limit 2745.3 W, 9 N·m at s_t = 0.1000 mm/tooth": the limits that shape P_av(N), in shop units.
QString powerLimitLabel(const app::MachineSpec& m, double feed_mm_per_tooth, const widgets::ShopUnits& units) {
  QString limits = units.format(widgets::Quantity::Power, m.spindle_power_W);
  if (m.max_torque_Nm) limits += QObject::tr(", %1 N\u00b7m").arg(*m.max_torque_Nm);
  if (m.spindle_curve) limits += QObject::tr(", power curve");
  return QObject::tr("power limit %1 at s_t = %2")
      .arg(limits, units.format(widgets::Quantity::ChipLoad, feed_mm_per_tooth));
}
}  // namespace

void LobesFeature::showPoint(const app::PickedPoint& point) {
  chart_->setOperatingPoint(point.speed_rpm, point.depth_mm, verdict_);  // recoloured when evaluated
  feed_spin_->blockSignals(true);
  feed_spin_->setValue(context_.units()->shop().fromBase(widgets::Quantity::ChipLoad, point.feed_mm_per_tooth));
  feed_spin_->blockSignals(false);
  requestReadout(point);
}

// The power-limit curve depends on the evaluator, the tool and s_t: it is recomputed with the readout
// only when one of them changed.
void LobesFeature::requestReadout(const app::PickedPoint& point) {
  if (context_.project().tools.empty()) return;  // the readout says "No tool" (showNoTools)
  PointJob job{evaluator_, evaluator_->toolIndex(context_.activeTool()), point, false};
  job.with_power_limit = evaluator_ != power_limit_evaluator_ || job.tool != power_limit_tool_ ||
                         point.feed_mm_per_tooth != power_limit_feed_;
  if (job.with_power_limit) {
    power_limit_evaluator_ = evaluator_;
    power_limit_tool_ = job.tool;
    power_limit_feed_ = point.feed_mm_per_tooth;
  }
  point_runner_->submit(std::move(job));
}

// Every answer for the lobes shown updates the panel (a drag shows its progress); only the latest
// request's answer colours the marker and becomes the readout the other features read. An answer from
// lobes no longer shown (another project, a recomputation, no tool left) is dropped: it would put the
// old project's point, or "no lobes computed yet", over what the panel now says.
void LobesFeature::onPointEvaluated(const PointJobResult& result) {
  if (result.evaluator != evaluator_) return;
  if (result.power_limit_mm) {
    const app::Project& p = context_.project();
    const double feed = result.point.feed_mm_per_tooth;
    chart_->setPowerLimit(*result.power_limit_mm,
                          p.machine ? powerLimitLabel(*p.machine, feed, context_.units()->shop()) : QString());
    lowerInitialPoint(result);
  }
  if (!result.readout) return;
  readout_->setReadout(*result.readout);
  if (result.generation != point_runner_->latestGeneration()) return;
  shown_generation_ = result.generation;
  showVerdict(*result.readout);
}

void LobesFeature::showVerdict(const widgets::PointReadout& r) {
  verdict_ = widgets::PointVerdict::Unknown;
  if (r.valid)
    verdict_ = r.marginal                     ? widgets::PointVerdict::Marginal
               : !r.stable                    ? widgets::PointVerdict::Unstable
               : !r.powerOk() || !r.forceOk() ? widgets::PointVerdict::LimitExceeded
                                              : widgets::PointVerdict::Stable;
  const app::PickedPoint& point = context_.point();
  chart_->setOperatingPoint(point.speed_rpm, point.depth_mm, verdict_);
  readout_->setSimulation(context_.simulationCheck());
  showStatusPoint();
  context_.setReadout(r);
  emit readoutShown();
}

// "Point: 4200 rpm, b = 1.3900 mm, s_t = 0.1000 mm/tooth — STABLE", in shop units.
void LobesFeature::showStatusPoint() {
  const app::PickedPoint& point = context_.point();
  const widgets::ShopUnits& units = context_.units()->shop();
  status_point_->setText(tr("Point: %1 rpm, b = %2, s_t = %3 \u2014 %4")
                             .arg(point.speed_rpm, 0, 'f', 0)
                             .arg(units.format(widgets::Quantity::Length, point.depth_mm),
                                  units.format(widgets::Quantity::ChipLoad, point.feed_mm_per_tooth),
                                  readout_->text("verdict")));
}

void LobesFeature::showActiveTool() {
  const QString& id = context_.activeTool();
  const int index = tool_combo_->findText(id);
  if (index >= 0 && tool_combo_->currentIndex() != index) tool_combo_->setCurrentIndex(index);
  chart_->setActiveTool(evaluator_->toolIndex(id));
  showModelLabel();
  showMethodAdvice();
  showPoint(context_.point());
}

// The model of the lobes shown, from the snapshot they were computed on.
void LobesFeature::showModelLabel() {
  const int tool = snapshot_ ? evaluator_->toolIndex(context_.activeTool()) : -1;
  if (tool < 0) {
    chart_->setModelLabel({});
    return;
  }
  const MillingSetup& setup = snapshot_->tools[std::size_t(tool)].setup;
  chart_->setModelLabel(
      tr("Tool %1: %2").arg(QString::fromStdString(setup.tool_id), widgets::modelLabel(snapshot_->method, setup)));
}

void LobesFeature::showMethodAdvice() {
  QString advice;
  const app::Project& p = context_.project();
  if (p.findTool(context_.activeTool()) != nullptr) {
    try {
      advice = widgets::methodAdvice(method_, p.setupFor(context_.activeTool()));
    } catch (const app::ProjectError&) {
      // no setup (e.g. no operation section): the lobes say why
    }
  }
  const QString base =
      tr("Stability method: ZOA (fast; averages the cut, ignores the helix and pitch differences; "
         "accurate at high radial immersion) or semi-discretization (SDM: models pitch and helix; "
         "low immersion, few teeth)");
  method_combo_->setToolTip(advice.isEmpty() ? base : base + "\n\n" + advice);
  if (!advice.isEmpty() && advice != method_advice_->text()) emit statusMessage(advice, 8000);
  method_advice_->setText(advice);
  method_advice_->setVisible(!advice.isEmpty());
}

void LobesFeature::onPointDragged(double speed_rpm, double depth_mm) {
  app::PickedPoint p = context_.point();
  p.speed_rpm = speed_rpm;
  p.depth_mm = depth_mm;
  emit pointRequested(p, drag_id_);
}

}  // namespace mx::gui
