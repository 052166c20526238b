#include "control_feature.h"

#include <QDockWidget>

#include "control_runner.h"
#include "control_view.h"
#include "control_view_data.h"
#include "document/project_validation.h"
#include "feature_dock.h"

namespace mx::gui {

ControlFeature::ControlFeature(QMainWindow* window, const FeatureContext& context)
    : WindowFeature(window),
      document_(context.document()),
      runner_(new ControlRunner(context.enginePool(), this)),
      view_(new widgets::ControlView) {
  view_->setUnits(context.units());
  setObjectName("controlFeature");
  QDockWidget* dock = makeFeatureDock(window, tr("Force control"), "controlDock", view_, DockContent::Scrolling);
  window->addDockWidget(Qt::BottomDockWidgetArea, dock);
  if (auto* history = window->findChild<QDockWidget*>("historyDock")) window->tabifyDockWidget(history, dock);
  if (auto* simulation = window->findChild<QDockWidget*>("simulationDock")) simulation->raise();
  disable(tr("This project has no \"control\" section (docs/project-file.md)"));
  connectView();
  connectRunner();
}

void ControlFeature::stop() {
  runner_->cancel();
}

void ControlFeature::connectView() {
  connect(view_, &widgets::ControlView::betaChanged, this, [this](double beta) {
    // The debounced values of one slider drag carry its gesture: one undo step.
    editSection([beta](app::ControlRequest& r) { r.settings.beta = beta; }, tr("Change beta"), view_->betaGesture());
  });
  connect(view_, &widgets::ControlView::settingsEdited, this, [this](const widgets::ControllerSettingsView& v) {
    editSection([v](app::ControlRequest& r) { applyControllerSettings(v, r); }, tr("Change controller settings"));
  });
  connect(view_, &widgets::ControlView::workpieceEdited, this, [this](const QVector<widgets::DepthStepView>& steps) {
    editSection([steps](app::ControlRequest& r) { r.settings.workpiece = workpieceOf(steps, r.settings.workpiece); },
                tr("Change workpiece depth profile"));
  });
  connect(view_, &widgets::ControlView::sweepRequested, this, &ControlFeature::startSweep);
}

void ControlFeature::connectRunner() {
  connect(runner_, &ControlRunner::busyChanged, view_, &widgets::ControlView::setBusy);
  connect(runner_, &ControlRunner::finished, this, [this](const ControlOutcome& o) {
    if (!o.result) {
      if (o.error != "cancelled") view_->setStatus(tr("Closed loop failed: %1").arg(o.error));
      return;
    }
    view_->setTraces(controlTracesOf(*o.result));
    view_->setMetrics(controlMetricsOf(*o.result));
    view_->setPoleZero(poleZeroOf(*o.result));
    const ClosedLoopMetrics& m = o.result->metrics;
    // Rule 4 (Pareto paper) or a programme of several spindle speeds: the range of the sampling periods
    const QString period =
        m.max_sampling_period_s > m.min_sampling_period_s
            ? tr("%1-%2").arg(m.min_sampling_period_s * 1e3, 0, 'f', 2).arg(m.max_sampling_period_s * 1e3, 0, 'f', 2)
            : QString::number(o.result->sampling_period_s * 1e3, 'f', 2);
    view_->setStatus(tr("beta = %1: %2 samples (%3 spindle revolutions), T = %4 ms, tau_c = %5 ms%6")
                         .arg(o.result->beta)
                         .arg(m.samples)
                         .arg(m.spindle_revolutions, 0, 'f', 0)
                         .arg(period)
                         .arg(o.result->tau_c_s * 1e3, 0, 'f', 2)
                         .arg(m.completed ? QString() : tr(" - did not finish the workpiece")));
    emit controlShown();
  });
  connect(runner_, &ControlRunner::sweepFinished, this, [this](const SweepOutcome& o) {
    if (!o.result) {
      if (o.error != "cancelled") view_->setStatus(tr("beta sweep failed: %1").arg(o.error));
      return;
    }
    view_->setJcCurve(jcCurveOf(*o.result, o.threshold_beta));
    emit controlSweepShown();
  });
}

void ControlFeature::disable(const QString& status) {
  request_.reset();
  view_->setEnabled(false);
  view_->setStatus(status);
}

// The editors show the project's section, then the runs `recompute` names re-run (none: editors only).
void ControlFeature::projectChanged(const app::Project& project, Features recompute) {
  if (recompute && !(recompute & (Feature::ControlRun | Feature::ControlSweep))) return;  // none of its inputs
  if (!project.control) {
    disable(tr("This project has no \"control\" section (docs/project-file.md)"));
    return;
  }
  try {
    request_ = app::controlRequestFromProject(project);
  } catch (const std::exception& e) {
    disable(tr("Control section invalid: %1").arg(e.what()));
    return;
  }
  view_->setEnabled(true);
  view_->setBeta(request_->settings.beta);
  view_->setSettings(controllerSettingsOf(*request_));
  view_->setWorkpiece(workpieceViewOf(request_->settings.workpiece));
  if (recompute & Feature::ControlRun) runner_->run(request_->settings);
  if (recompute & Feature::ControlSweep) startSweep();
}

void ControlFeature::startSweep() {
  if (!request_) return;
  runner_->sweep(request_->settings, {-1.0, 1.0, 0.05, 1});
}

void ControlFeature::editSection(const std::function<void(app::ControlRequest&)>& change, const QString& what,
                                 int gesture) {
  if (!request_) return;
  app::ControlRequest r = *request_;
  change(r);
  app::Project edited = document_.project();
  edited.control = app::controlSectionFrom(r, edited.control.value_or(app::ControlSection{}));
  // The section's own validation (ranges, workpiece) before the edit is requested.
  try {
    app::validateProject(edited);
    app::controlRequestFromProject(edited);
  } catch (const std::exception& e) {
    emit errorRaised(what, e.what());
    projectChanged(document_.project(), {});  // the editors show the project's values again
    return;
  }
  emit editRequested(edited, what, gesture);
}

}  // namespace mx::gui
