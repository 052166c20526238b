// MainWindow: the supervisor view (issue 8; Landers & Ulsoy). The project's "supervisor" section gives
// the scenario and the Grafcet chart of each controller; the chart is drawn and edited (each valid edit
// is an undoable project change); a run streams F_Y, power, the active steps (tokens), module activity
// and events from the engine thread, paced so that the operator's feed hold and chatter buttons act on
// it; Compare runs none, SMC I and SMC II side by side.
#include <QDockWidget>
#include <QStatusBar>

#include "services/supervisor_request.h"
#include "grafcet_chart_editor.h"
#include "grafcet_chart_view.h"
#include "main_window.h"
#include "document/project_grafcet_io.h"
#include "supervision_runner.h"
#include "supervision_timeline.h"
#include "supervisor_comparison.h"
#include "supervisor_view.h"

namespace mx::gui {

namespace {

widgets::GrafcetChartData chartData(const GrafcetChart& c) {
  widgets::GrafcetChartData d;
  d.name = QString::fromStdString(c.name);
  for (const GrafcetStep& s : c.steps) {
    widgets::GrafcetStepView v{s.id, QString::fromStdString(s.name), s.initial, {}};
    for (const std::string& a : s.actions) v.actions << QString::fromStdString(a);
    d.steps.append(v);
  }
  for (const GrafcetTransition& t : c.transitions)
    d.transitions.append({t.id, QList<int>(t.from.begin(), t.from.end()), QList<int>(t.to.begin(), t.to.end()),
                          QString::fromStdString(t.receptivity), t.priority});
  return d;
}

GrafcetChart engineChart(const widgets::GrafcetChartData& d) {
  GrafcetChart c;
  c.name = d.name.toStdString();
  for (const widgets::GrafcetStepView& s : d.steps) {
    GrafcetStep step{s.id, s.name.toStdString(), s.initial, {}};
    for (const QString& a : s.actions) step.actions.push_back(a.toStdString());
    c.steps.push_back(step);
  }
  for (const widgets::GrafcetTransitionView& t : d.transitions)
    c.transitions.push_back({t.id, std::vector<int>(t.from.begin(), t.from.end()),
                             std::vector<int>(t.to.begin(), t.to.end()), t.receptivity.toStdString(), t.priority});
  return c;
}

widgets::SupervisionSeries seriesOf(const std::vector<SupervisionSample>& samples, const SupervisionScenario& s,
                                    double reference_n) {
  widgets::SupervisionSeries out;
  for (const SupervisionSample& x : samples) {
    out.t_s << x.t_s;
    out.force_y_n << x.F_Y_N;
    out.power_w << x.power_W;
    out.feed_mm_s << x.feed_m_per_s * 1e3;
  }
  out.power_limit_w = s.limits.spindle_power_limit_W;
  out.force_reference_n = reference_n;
  return out;
}

widgets::SupervisionMetricsView metricsOf(const QString& controller, const SupervisionMetrics& m) {
  widgets::SupervisionMetricsView v;
  v.controller = controller;
  v.max_power_pct_of_limit = m.max_power_pct_of_limit;
  v.overshoot_pct = m.overshoot_pct;
  v.chatter_detected = m.chatter_detected;
  if (m.chatter_time_s >= 0.0) v.chatter_time_s = m.chatter_time_s;
  v.passes = m.passes;
  v.cycle_time_s = m.cycle_time_s;
  return v;
}

// Module activity records (the active letters whenever the set changes) as spans per letter.
QVector<widgets::ModuleSpan> moduleSpans(const std::vector<ModuleActivityRecord>& records, double end_s) {
  QVector<widgets::ModuleSpan> spans;
  std::map<char, double> open;
  auto close = [&](char m, double t) {
    spans.append({QString(QChar(m)), open[m], t});
    open.erase(m);
  };
  for (const ModuleActivityRecord& r : records) {
    for (auto it = open.begin(); it != open.end();) {
      const char m = it->first;
      ++it;
      if (r.active.find(m) == std::string::npos) close(m, r.t_s);
    }
    for (char m : r.active)
      if (!open.count(m)) open[m] = r.t_s;
  }
  while (!open.empty()) close(open.begin()->first, end_s);
  return spans;
}

}  // namespace

void MainWindow::buildSupervisorDock() {
  supervision_ = new SupervisionRunner(engine_->pool(), this);
  supervisor_view_ = new widgets::SupervisorView;
  auto* dock = new QDockWidget(tr("Supervisor"), this);
  dock->setObjectName("supervisorDock");
  dock->setWidget(supervisor_view_);
  addDockWidget(Qt::BottomDockWidgetArea, dock);
  if (auto* program = findChild<QDockWidget*>("partProgramDock")) tabifyDockWidget(program, dock);
  if (auto* simulation = findChild<QDockWidget*>("simulationDock")) simulation->raise();
  supervisor_view_->setControllers(app::supervisorControllers());
  supervisor_view_->setEnabled(false);
  supervisor_view_->editor()->setValidator([](const widgets::GrafcetChartData& d) {
    QList<widgets::ChartIssue> issues;
    for (const GrafcetIssue& i : validateGrafcetChart(engineChart(d), app::supervisionSignals())) {
      widgets::ChartIssue issue;
      issue.message = QString::fromStdString(i.describe());
      if (i.element == GrafcetElement::Step) {
        issue.step_id = i.id;
        issue.element = QString("step %1").arg(i.id);
      } else if (i.element == GrafcetElement::Transition) {
        issue.transition_id = i.id;
        issue.element = QString("transition %1").arg(i.id);
      } else {
        issue.element = "chart";
      }
      issues.append(issue);
    }
    return issues;
  });
  connect(supervisor_view_, &widgets::SupervisorView::controllerChanged, this, [this] { refreshSupervisor(); });
  connect(supervisor_view_, &widgets::SupervisorView::runRequested, this, &MainWindow::startSupervision);
  connect(supervisor_view_, &widgets::SupervisorView::stopRequested, supervision_, &SupervisionRunner::stop);
  connect(supervisor_view_, &widgets::SupervisorView::feedHoldToggled, this, [this](bool on) {
    supervision_->inject(on ? OperatorEventType::FeedHoldOn : OperatorEventType::FeedHoldOff);
  });
  connect(supervisor_view_, &widgets::SupervisorView::chatterSignalled, this,
          [this] { supervision_->inject(OperatorEventType::ChatterSignal); });
  connect(supervisor_view_, &widgets::SupervisorView::compareRequested, this, &MainWindow::compareSupervision);
  connect(supervisor_view_->editor(), &widgets::GrafcetChartEditor::chartEdited, this,
          [this](const widgets::GrafcetChartData& d) {
            app::Project edited = doc_.project();
            if (!edited.supervisor) return;
            const QString c = supervisor_view_->controller();
            if (!edited.supervisor->charts) edited.supervisor->charts.emplace();
            std::optional<app::GrafcetChartSpec>* chart = edited.supervisor->charts->of(c);
            if (!chart) return;
            *chart = app::grafcetChartSpecWith(chart->value_or(app::GrafcetChartSpec{}), engineChart(d));
            const QString error = doc_.applyEdit(edited, tr("Edit the %1 chart").arg(c));
            if (!error.isEmpty()) showError(tr("Chart refused"), error);
          });
  connect(supervision_, &SupervisionRunner::runningChanged, supervisor_view_, &widgets::SupervisorView::setRunning);
  connect(supervision_, &SupervisionRunner::chunkReady, this, [this](const SupervisionChunk& c) {
    if (!supervisor_request_ || c.generation == 0) return;
    const double ref = supervisor_request_->scenario.reference_force_N;
    supervisor_view_->timeline()->appendSeries(seriesOf(c.samples, supervisor_request_->scenario, ref));
    QVector<widgets::SupervisionEventView> events;
    for (const SupervisionEvent& e : c.events)
      events.append({e.t_s, QString::fromStdString(e.type), QString::fromStdString(e.detail)});
    supervisor_view_->timeline()->appendEvents(events);
    if (!c.steps.empty()) {
      QList<int> ids;
      for (const std::string& name : c.steps.back().steps)
        for (const GrafcetStep& s : supervisor_request_->chart.steps)
          if (s.name == name) ids << s.id;
      supervisor_view_->chartView()->setActiveSteps(ids);
    }
    live_modules_.insert(live_modules_.end(), c.modules.begin(), c.modules.end());
    if (!c.samples.empty()) supervisor_view_->timeline()->setModuleSpans(moduleSpans(live_modules_, c.samples.back().t_s));
  });
  connect(supervision_, &SupervisionRunner::finished, this, [this](const SupervisionOutcome& o) {
    if (!o.result) {
      supervisor_view_->setStatus(tr("Run %1: %2").arg(o.controller, o.error));
      return;
    }
    const SupervisionResult& r = *o.result;
    supervisor_view_->timeline()->setSeries(seriesOf(r.series, supervisor_request_->scenario, r.metrics.reference_force_N));
    supervisor_view_->timeline()->setModuleSpans(moduleSpans(r.modules, r.metrics.cycle_time_s));
    supervisor_view_->setMetrics(metricsOf(o.controller, r.metrics));
    supervisor_view_->setStatus(tr("%1: %2 pass(es), cycle %3 s, F_ref %4 N")
                                    .arg(o.controller)
                                    .arg(r.metrics.passes)
                                    .arg(r.metrics.cycle_time_s, 0, 'f', 2)
                                    .arg(r.metrics.reference_force_N, 0, 'f', 1));
    emit supervisionFinished();
  });
  connect(supervision_, &SupervisionRunner::compared, this, [this](const SupervisionOutcome& o) {
    if (!o.result) return;
    const SupervisionResult& r = *o.result;
    app::SupervisorRequest req = app::supervisorRequestFromProject(doc_.project(), o.controller);
    supervisor_view_->comparison()->setResult(o.controller, seriesOf(r.series, req.scenario, r.metrics.reference_force_N),
                                              metricsOf(o.controller, r.metrics));
    emit comparisonResult(o.controller);
  });
}

void MainWindow::refreshSupervisor() {
  const app::Project& p = doc_.project();
  if (!p.supervisor) {
    supervisor_request_.reset();
    supervisor_view_->setEnabled(false);
    supervisor_view_->setStatus(tr("This project has no \"supervisor\" section (docs/project-file.md)"));
    return;
  }
  try {
    supervisor_request_ = app::supervisorRequestFromProject(p, supervisor_view_->controller());
  } catch (const std::exception& e) {
    supervisor_request_.reset();
    supervisor_view_->setStatus(tr("Supervisor section invalid: %1").arg(e.what()));
    // The editor still shows the chart, so that it can be mended.
    const auto* chart = p.supervisor->charts ? p.supervisor->charts->of(supervisor_view_->controller()) : nullptr;
    if (chart && *chart) supervisor_view_->editor()->setChart(chartData((*chart)->chart));
    return;
  }
  supervisor_view_->setEnabled(true);
  const widgets::GrafcetChartData data = chartData(supervisor_request_->chart);
  supervisor_view_->chartView()->setChart(data);
  if (!(supervisor_view_->editor()->chart() == data)) supervisor_view_->editor()->setChart(data);
}

void MainWindow::startSupervision() {
  if (!supervisor_request_) return;
  supervision_shown_ = SupervisionShown::Run;
  supervisor_view_->timeline()->clear();
  live_modules_.clear();
  SupervisionScenario s = supervisor_request_->scenario;
  if (!(s.reference_force_N > 0.0)) s.reference_force_N = referenceForceFromPower(s);
  supervisor_request_->scenario.reference_force_N = s.reference_force_N;
  supervision_->start(s, supervisor_request_->chart, supervisor_view_->speedFactor());
}

void MainWindow::compareSupervision() {
  std::vector<std::pair<SupervisionScenario, GrafcetChart>> runs;
  try {
    for (const QString& c : app::supervisorControllers()) {
      const app::SupervisorRequest r = app::supervisorRequestFromProject(doc_.project(), c);
      runs.emplace_back(r.scenario, r.chart);
    }
  } catch (const std::exception& e) {
    showError(tr("Compare controllers"), e.what());
    return;
  }
  supervision_shown_ = SupervisionShown::Comparison;
  supervisor_view_->comparison()->clear();
  supervision_->compare(runs);
}

}  // namespace mx::gui
