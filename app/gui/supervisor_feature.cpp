#include "supervisor_feature.h"

#include <QDockWidget>

#include "document/project_grafcet_io.h"
#include "document/project_validation.h"
#include "feature_dock.h"
#include "grafcet_chart_editor.h"
#include "grafcet_chart_view.h"
#include "supervision_runner.h"
#include "supervision_timeline.h"
#include "supervisor_comparison.h"
#include "supervisor_view.h"
#include "supervisor_view_data.h"

namespace mx::gui {

SupervisorFeature::SupervisorFeature(QMainWindow* window, const FeatureContext& context)
    : WindowFeature(window),
      document_(context.document()),
      runner_(new SupervisionRunner(context.enginePool(), this)),
      view_(new widgets::SupervisorView) {
  setObjectName("supervisorFeature");
  units_ = context.units();
  view_->timeline()->setUnits(context.units());
  view_->comparison()->setUnits(context.units());
  QDockWidget* dock = makeFeatureDock(window, tr("Supervisor"), "supervisorDock", view_, DockContent::Scrolling);
  window->addDockWidget(Qt::BottomDockWidgetArea, dock);
  if (auto* program = window->findChild<QDockWidget*>("partProgramDock")) window->tabifyDockWidget(program, dock);
  if (auto* simulation = window->findChild<QDockWidget*>("simulationDock")) simulation->raise();
  view_->setControllers(app::supervisorControllers());
  view_->setEnabled(false);
  view_->editor()->setValidator(chartIssues);
  connectView();
  connectRunner();
}

void SupervisorFeature::stop() {
  runner_->stop();
}

void SupervisorFeature::connectView() {
  connect(view_, &widgets::SupervisorView::controllerChanged, this, [this] { refresh(document_.project()); });
  connect(view_, &widgets::SupervisorView::runRequested, this, &SupervisorFeature::start);
  connect(view_, &widgets::SupervisorView::stopRequested, runner_, &SupervisionRunner::stop);
  connect(view_, &widgets::SupervisorView::feedHoldToggled, this,
          [this](bool on) { runner_->inject(on ? OperatorEventType::FeedHoldOn : OperatorEventType::FeedHoldOff); });
  connect(view_, &widgets::SupervisorView::chatterSignalled, this,
          [this] { runner_->inject(OperatorEventType::ChatterSignal); });
  connect(view_, &widgets::SupervisorView::compareRequested, this, &SupervisorFeature::compare);
  connect(view_, &widgets::SupervisorView::timeConstantEdited, this, [this](double ms) {
    editModelController([ms](app::SupervisorModelControllerSpec& m) { m.time_constant_ms = ms; },
                        tr("Set module L's force time constant \u03c4 to %1 ms").arg(ms));
  });
  connect(view_, &widgets::SupervisorView::resetFeedEdited, this, [this](const QString& name) {
    editModelController([name](app::SupervisorModelControllerSpec& m) { m.reset_feed = name; },
                        tr("Set module L's restart at contact to '%1'").arg(name));
  });
  connect(view_->editor(), &widgets::GrafcetChartEditor::chartEdited, this,
          [this](const widgets::GrafcetChartData& d) { requestChartEdit(view_->controller(), engineChart(d)); });
}

void SupervisorFeature::connectRunner() {
  connect(runner_, &SupervisionRunner::runningChanged, view_, &widgets::SupervisorView::setRunning);
  connect(runner_, &SupervisionRunner::chunkReady, this, &SupervisorFeature::onChunk);
  connect(runner_, &SupervisionRunner::finished, this, &SupervisorFeature::onFinished);
  connect(runner_, &SupervisionRunner::compared, this, &SupervisorFeature::onCompared);
}

void SupervisorFeature::requestChartEdit(const QString& controller, const GrafcetChart& chart) {
  app::Project edited = document_.project();
  if (!edited.supervisor) return;
  if (!edited.supervisor->charts) edited.supervisor->charts.emplace();
  std::optional<app::GrafcetChartSpec>* spec = edited.supervisor->charts->of(controller);
  if (!spec) return;
  *spec = app::grafcetChartSpecWith(spec->value_or(app::GrafcetChartSpec{}), chart);
  emit editRequested(edited, tr("Edit the %1 chart").arg(controller), 0);
}

// The project's values, the engine's defaults for what the section leaves out.
void SupervisorFeature::showModelController(const app::SupervisorSection& section) {
  const SupervisionScenario defaults;
  const app::SupervisorModelControllerSpec m = section.model_controller.value_or(app::SupervisorModelControllerSpec{});
  view_->setModelController(m.time_constant_ms.value_or(defaults.force_time_constant_s * 1e3),
                            m.reset_feed.value_or(QString::fromStdString(resetFeedName(defaults.force_reset_feed))));
}

// One undoable edit of supervisor.model_controller. A value the project's rules refuse is named with its
// range (the document's message), changes nothing, and the view shows the project's values again.
void SupervisorFeature::editModelController(const std::function<void(app::SupervisorModelControllerSpec&)>& change,
                                            const QString& description) {
  app::Project edited = document_.project();
  if (!edited.supervisor) return;
  std::optional<app::SupervisorModelControllerSpec>& spec = edited.supervisor->model_controller;
  if (!spec) spec.emplace();
  change(*spec);
  const QString error = app::projectValidationError(edited);
  if (!error.isEmpty()) {
    emit errorRaised(description, error);
    showModelController(*document_.project().supervisor);
    return;
  }
  emit editRequested(edited, description, 0);
}

void SupervisorFeature::onChunk(const SupervisionChunk& c) {
  if (!request_ || c.generation == 0) return;
  const double ref = request_->scenario.reference_force_N;
  view_->timeline()->appendSeries(supervisionSeriesOf(c.samples, request_->scenario, ref));
  QVector<widgets::SupervisionEventView> events;
  for (const SupervisionEvent& e : c.events)
    events.append({e.t_s, QString::fromStdString(e.type), QString::fromStdString(e.detail)});
  view_->timeline()->appendEvents(events);
  if (!c.steps.empty()) {
    QList<int> ids;
    for (const std::string& name : c.steps.back().steps)
      for (const GrafcetStep& s : request_->chart.steps)
        if (s.name == name) ids << s.id;
    view_->chartView()->setActiveSteps(ids);
  }
  live_modules_.insert(live_modules_.end(), c.modules.begin(), c.modules.end());
  if (!c.samples.empty()) view_->timeline()->setModuleSpans(moduleSpans(live_modules_, c.samples.back().t_s));
}

void SupervisorFeature::onFinished(const SupervisionOutcome& o) {
  if (!o.result) {
    view_->setStatus(tr("Run %1: %2").arg(o.controller, o.error));
    return;
  }
  const SupervisionResult& r = *o.result;
  view_->timeline()->setSeries(supervisionSeriesOf(r.series, request_->scenario, r.metrics.reference_force_N));
  view_->timeline()->setModuleSpans(moduleSpans(r.modules, r.metrics.cycle_time_s));
  view_->setMetrics(supervisionMetricsOf(o.controller, r.metrics));
  view_->setStatus(tr("%1: %2 pass(es), cycle %3 s, F_ref %4")
                       .arg(o.controller)
                       .arg(r.metrics.passes)
                       .arg(r.metrics.cycle_time_s, 0, 'f', 2)
                       .arg(units_->shop().format(widgets::Quantity::Force, r.metrics.reference_force_N)));
  emit supervisionFinished();
}

void SupervisorFeature::onCompared(const SupervisionOutcome& o) {
  if (!o.result) return;
  const SupervisionResult& r = *o.result;
  const app::SupervisorRequest req = app::supervisorRequestFromProject(document_.project(), o.controller);
  view_->comparison()->setResult(o.controller, supervisionSeriesOf(r.series, req.scenario, r.metrics.reference_force_N),
                                 supervisionMetricsOf(o.controller, r.metrics));
  emit comparisonResult(o.controller);
}

void SupervisorFeature::projectChanged(const app::Project& project, Features recompute) {
  if (!(recompute & Feature::Supervisor)) return;
  refresh(project);
  if (!request_) shown_ = Shown::None;
  if (shown_ == Shown::Run) start();
  if (shown_ == Shown::Comparison) compare();
}

void SupervisorFeature::refresh(const app::Project& p) {
  if (!p.supervisor) {
    request_.reset();
    view_->setEnabled(false);
    view_->setStatus(tr("This project has no \"supervisor\" section (docs/project-file.md)"));
    return;
  }
  showModelController(*p.supervisor);
  try {
    request_ = app::supervisorRequestFromProject(p, view_->controller());
  } catch (const std::exception& e) {
    request_.reset();
    view_->setStatus(tr("Supervisor section invalid: %1").arg(e.what()));
    // The editor still shows the chart, so that it can be mended.
    const auto* chart = p.supervisor->charts ? p.supervisor->charts->of(view_->controller()) : nullptr;
    if (chart && *chart) view_->editor()->setChart(chartData((*chart)->chart));
    return;
  }
  view_->setEnabled(true);
  if (shown_ == Shown::None)
    view_->setStatus(
        tr("Supervisor ready (controller %1): Run simulates the supervised cycle, Compare runs all controllers")
            .arg(view_->controller()));
  const widgets::GrafcetChartData data = chartData(request_->chart);
  view_->chartView()->setChart(data);
  if (!(view_->editor()->chart() == data)) view_->editor()->setChart(data);
}

void SupervisorFeature::start() {
  if (!request_) return;
  shown_ = Shown::Run;
  view_->timeline()->clear();
  live_modules_.clear();
  SupervisionScenario s = request_->scenario;
  if (!(s.reference_force_N > 0.0)) s.reference_force_N = referenceForceFromPower(s);
  request_->scenario.reference_force_N = s.reference_force_N;
  runner_->start(s, request_->chart, view_->speedFactor());
}

void SupervisorFeature::compare() {
  std::vector<std::pair<SupervisionScenario, GrafcetChart>> runs;
  try {
    for (const QString& c : app::supervisorControllers()) {
      const app::SupervisorRequest r = app::supervisorRequestFromProject(document_.project(), c);
      runs.emplace_back(r.scenario, r.chart);
    }
  } catch (const std::exception& e) {
    emit errorRaised(tr("Compare controllers"), e.what());
    return;
  }
  shown_ = Shown::Comparison;
  view_->comparison()->clear();
  runner_->compare(runs);
}

}  // namespace mx::gui
