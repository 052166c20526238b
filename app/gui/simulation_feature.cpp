#include "simulation_feature.h"

#include <QDockWidget>
#include <cmath>
#include <limits>

#include "feature_dock.h"
#include "services/measured_dynamics.h"
#include "simulation_runner.h"
#include "simulation_view.h"

namespace mx::gui {

SimulationFeature::SimulationFeature(QMainWindow* window, FeatureContext& context)
    : WindowFeature(window),
      context_(context),
      runner_(new SimulationRunner(context.enginePool(), this)),
      view_(new widgets::SimulationView(window)) {
  setObjectName("simulationFeature");
  view_->setUnits(context.units());
  window->addDockWidget(Qt::BottomDockWidgetArea,
                        makeFeatureDock(window, tr("Live simulation"), "simulationDock", view_));
  connect(runner_, &SimulationRunner::chunkReady, this, [this](quint64 g, const SimulationChunkData& chunk) {
    if (g == generation_) view_->appendChunk(chunk);
  });
  connect(runner_, &SimulationRunner::finished, this, &SimulationFeature::onFinished);
  connect(runner_, &SimulationRunner::failed, this, [this](quint64 g, const QString& message) {
    if (g != generation_) return;
    view_->setStatus(tr("Simulation failed: %1").arg(message));
    context_.clearSimulation();
  });
  connect(view_, &widgets::SimulationView::moveToPointRequested, this, [this](double rpm, double depth_mm) {
    app::PickedPoint p = context_.point();
    p.speed_rpm = rpm;
    if (std::isfinite(depth_mm)) p.depth_mm = depth_mm;
    emit pointRequested(p, 0);
    start();
  });
  connect(&context_, &FeatureContext::simulationRequested, this, &SimulationFeature::start);
  rerun_timer_.setSingleShot(true);
  rerun_timer_.setInterval(400);
  connect(&rerun_timer_, &QTimer::timeout, this, &SimulationFeature::start);
  connect(&context_.document(), &app::ProjectDocument::pointChanged, this, &SimulationFeature::onPointOrToolChanged);
  connect(&context_, &FeatureContext::activeToolChanged, this, &SimulationFeature::onPointOrToolChanged);
}

bool SimulationFeature::runIsOfCurrentState() const {
  return context_.activeTool() == shown_tool_ && context_.point() == shown_point_;
}

void SimulationFeature::onPointOrToolChanged() {
  if (runIsOfCurrentState()) return;
  if (!view_->isStale() && !shown_tool_.isEmpty()) {
    view_->setStale(
        context_.activeTool() != shown_tool_
            ? tr("the run is of tool %1; the active tool is %2").arg(shown_tool_, context_.activeTool())
            : tr("the run is of %1 rpm, %2, %3; the point moved")
                  .arg(shown_point_.speed_rpm, 0, 'f', 0)
                  .arg(context_.units()->shop().format(widgets::Quantity::Length, shown_point_.depth_mm),
                       context_.units()->shop().format(widgets::Quantity::ChipLoad, shown_point_.feed_mm_per_tooth)));
  }
  rerun_timer_.start();
}

void SimulationFeature::showCannotSimulate(const QString& reason) {
  runner_->cancel();
  ++generation_;  // a late chunk of the cancelled run is dropped
  view_->clear();
  view_->setStatus(tr("Cannot simulate: %1").arg(reason));
  shown_tool_ = context_.activeTool();
  shown_point_ = context_.point();
  context_.clearSimulation();
}

void SimulationFeature::addViewActions(QMenu* view, QToolBar* toolbar) {
  QAction* a = view->addAction(tr("Simulate the &point"));
  a->setShortcut(QKeySequence(tr("F5")));
  a->setToolTip(tr("Run the time-domain simulation of the point"));
  a->setStatusTip(a->toolTip());
  connect(a, &QAction::triggered, this, &SimulationFeature::start);
  toolbar->addAction(a);
}

void SimulationFeature::projectChanged(const app::Project& /*project*/, Features recompute) {
  if (recompute & Feature::Simulation) start();
}

void SimulationFeature::projectReplaced() {
  runner_->cancel();
  ++generation_;
  view_->clear();
  shown_tool_.clear();
  shown_point_ = {};
  context_.clearSimulation();
}

void SimulationFeature::stop() {
  runner_->cancel();
}

void SimulationFeature::start() {
  rerun_timer_.stop();
  const app::Project& p = context_.project();
  const app::PickedPoint& pt = context_.point();
  if (context_.activeTool().isEmpty() || pt.speed_rpm <= 0.0 || pt.feed_mm_per_tooth <= 0.0) return;
  if (!p.findTool(context_.activeTool())) return;  // the tool list is being refreshed; its change re-runs
  try {
    const MillingSetup setup = p.setupFor(context_.activeTool());
    app::requireFittedModes(*p.findTool(context_.activeTool()), tr("the time-domain simulation"));
    SimulationOptions options;
    options.revolutions = 60;
    const double power = p.machine ? app::availablePowerW(p.machine, pt.speed_rpm) : 0.0;  // P_av(N)
    const double max_speed = p.machine && p.machine->max_spindle_rpm ? rpmToRevPerS(*p.machine->max_spindle_rpm)
                                                                     : std::numeric_limits<double>::infinity();
    const OperatingPoint op{rpmToRevPerS(pt.speed_rpm), pt.depth_mm * 1e-3, pt.feed_mm_per_tooth * 1e-3};
    generation_ = runner_->submit(setup, op, options, power, max_speed);
    view_->beginRun(power, setup.teeth, op.spindle_rev_per_s * setup.teeth);
    shown_tool_ = context_.activeTool();
    shown_point_ = pt;
    context_.setSimulationRunning(shown_tool_, shown_point_);
  } catch (const std::exception& e) {
    showCannotSimulate(QString::fromUtf8(e.what()));
  }
}

void SimulationFeature::onFinished(quint64 generation, const SimulationSummary& result) {
  if (generation != generation_) return;
  // The point or the tool moved while it ran: the view stays stale until the re-run for the new state
  // (rerun_timer_) shows, instead of giving this run's verdict as the current one.
  if (!runIsOfCurrentState()) {
    context_.clearSimulation();
    return;
  }
  SimulationSummary summary = result;
  if (summary.chatter) checkSuggestion(summary);
  view_->setSummary(summary);
  context_.setSimulationResult(summary);
  emit context_.simulationFinished(summary);
  emit simulationShown();
}

void SimulationFeature::checkSuggestion(SimulationSummary& s) const {
  s.suggested_rpm.reset();
  s.suggested_k = 0;
  const PointEvaluator& lobes = *context_.evaluator();
  const int tool = lobes.toolIndex(shown_tool_);
  const app::Project& p = context_.project();
  const double max_rpm =
      p.machine && p.machine->max_spindle_rpm ? *p.machine->max_spindle_rpm : std::numeric_limits<double>::infinity();
  const app::PickedPoint& at = shown_point_;
  const auto q = lobes.suggestStablePoint(tool, at.speed_rpm, at.depth_mm, s.chatter_frequency_hz, max_rpm);
  if (!q) {
    s.suggestion_note = tr("No lobes of tool %1 in the machine's speed range to check a speed on").arg(shown_tool_);
    return;
  }
  const double rpm = revPerSToRpm(q->speed_rev_per_s);
  const double blim = lobes.depthLimitMm(tool, rpm);
  s.suggested_rpm = rpm;
  switch (q->kind) {
    case StablePointSuggestion::Kind::SmithTlusty:
      s.suggested_k = q->k;
      s.suggestion_note = tr("Smith-Tlusty speed (k = %1), stable on the lobes: b_lim = %2 mm at %3 rpm")
                              .arg(q->k)
                              .arg(blim, 0, 'f', 3)
                              .arg(rpm, 0, 'f', 0);
      break;
    case StablePointSuggestion::Kind::NearestStableSpeed:
      s.suggestion_note = tr("No Smith-Tlusty speed is stable at %1 mm; %2 rpm is the peak of the nearest stable "
                             "pocket (b_lim = %3 mm)")
                              .arg(at.depth_mm, 0, 'f', 3)
                              .arg(rpm, 0, 'f', 0)
                              .arg(blim, 0, 'f', 3);
      break;
    case StablePointSuggestion::Kind::ShallowerDepth: {
      const auto [lo, hi] = lobes.speedRangeRpm(tool);
      s.suggested_depth_mm = q->depth_m * 1e3;
      s.suggestion_note = tr("No speed in %1-%2 rpm is stable at %3 mm: the deepest stable depth at the nearest "
                             "pocket (%4 rpm) is %5 mm")
                              .arg(lo, 0, 'f', 0)
                              .arg(std::min(hi, max_rpm), 0, 'f', 0)
                              .arg(at.depth_mm, 0, 'f', 3)
                              .arg(rpm, 0, 'f', 0)
                              .arg(*s.suggested_depth_mm, 0, 'f', 3);
      break;
    }
  }
}

}  // namespace mx::gui
