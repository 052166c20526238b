// MainWindow: the control view (issue 6; 2006 paper, section 4). The project's "control" section
// drives the adaptive beta-FROH closed loop on the engine thread; the view's beta slider, controller
// settings and workpiece editors are undoable edits of that section (one per slider drag). A change of
// its inputs re-runs the closed loop; a change other than beta also re-runs the J_c(beta) sweep.
#include <QDockWidget>
#include <QStatusBar>

#include "control_runner.h"
#include "control_view.h"
#include "control_view_data.h"
#include "main_window.h"
#include "document/project_validation.h"

namespace mx::gui {

void MainWindow::buildControlDock() {
  control_runner_ = new ControlRunner(engine_->pool(), this);
  control_view_ = new widgets::ControlView;
  auto* dock = new QDockWidget(tr("Force control"), this);
  dock->setObjectName("controlDock");
  dock->setWidget(control_view_);
  addDockWidget(Qt::BottomDockWidgetArea, dock);
  if (auto* history = findChild<QDockWidget*>("historyDock")) tabifyDockWidget(history, dock);
  if (auto* simulation = findChild<QDockWidget*>("simulationDock")) simulation->raise();
  control_view_->setEnabled(false);
  control_view_->setStatus(tr("This project has no \"control\" section (docs/project-file.md)"));

  connect(control_view_, &widgets::ControlView::betaChanged, this, [this](double beta) {
    // The debounced values of one slider drag are one undo step.
    const int drag = control_view_->betaGesture();
    if (drag != beta_drag_) {
      beta_drag_ = drag;
      beta_gesture_ = drag > 0 ? doc_.newGesture() : 0;
    }
    editControlSection([beta](app::ControlRequest& r) { r.settings.beta = beta; }, tr("Change beta"), beta_gesture_);
  });
  connect(control_view_, &widgets::ControlView::settingsEdited, this, [this](const widgets::ControllerSettingsView& v) {
    editControlSection([v](app::ControlRequest& r) { applyControllerSettings(v, r); }, tr("Change controller settings"));
  });
  connect(control_view_, &widgets::ControlView::workpieceEdited, this,
          [this](const QVector<widgets::DepthStepView>& steps) {
            editControlSection([steps](app::ControlRequest& r) { r.settings.workpiece = workpieceOf(steps); },
                               tr("Change workpiece depth profile"));
          });
  connect(control_view_, &widgets::ControlView::sweepRequested, this, [this] { startControlSweep(); });
  connect(control_runner_, &ControlRunner::busyChanged, control_view_, &widgets::ControlView::setBusy);
  connect(control_runner_, &ControlRunner::finished, this, [this](const ControlOutcome& o) {
    if (!o.result) {
      if (o.error != "cancelled") control_view_->setStatus(tr("Closed loop failed: %1").arg(o.error));
      return;
    }
    control_view_->setTraces(controlTracesOf(*o.result));
    control_view_->setMetrics(controlMetricsOf(*o.result));
    control_view_->setPoleZero(poleZeroOf(*o.result));
    control_view_->setStatus(tr("beta = %1: %2 samples, T = %3 ms, tau_c = %4 ms%5")
                                 .arg(o.result->beta)
                                 .arg(o.result->metrics.samples)
                                 .arg(o.result->sampling_period_s * 1e3, 0, 'f', 2)
                                 .arg(o.result->tau_c_s * 1e3, 0, 'f', 2)
                                 .arg(o.result->metrics.completed ? QString() : tr(" - did not finish the workpiece")));
    emit controlShown();
  });
  connect(control_runner_, &ControlRunner::sweepFinished, this, [this](const SweepOutcome& o) {
    if (!o.result) {
      if (o.error != "cancelled") control_view_->setStatus(tr("beta sweep failed: %1").arg(o.error));
      return;
    }
    control_view_->setJcCurve(jcCurveOf(*o.result, o.threshold_beta));
    emit controlSweepShown();
  });
}

// The control view's inputs changed (or the project was loaded): refresh the editors, then the runs
// `features` name.
void MainWindow::refreshControl(Features features) {
  const app::Project& p = doc_.project();
  if (features && !(features & (Feature::ControlRun | Feature::ControlSweep))) return;  // none of its inputs
  if (!p.control) {
    control_request_.reset();
    control_view_->setEnabled(false);
    control_view_->setStatus(tr("This project has no \"control\" section (docs/project-file.md)"));
    return;
  }
  try {
    control_request_ = app::controlRequestFromProject(p);
  } catch (const std::exception& e) {
    control_request_.reset();
    control_view_->setEnabled(false);
    control_view_->setStatus(tr("Control section invalid: %1").arg(e.what()));
    return;
  }
  control_view_->setEnabled(true);
  control_view_->setBeta(control_request_->settings.beta);
  control_view_->setSettings(controllerSettingsOf(*control_request_));
  control_view_->setWorkpiece(workpieceViewOf(control_request_->settings.workpiece));
  if (features & Feature::ControlRun) control_runner_->run(control_request_->settings);
  if (features & Feature::ControlSweep) startControlSweep();
}

void MainWindow::startControlSweep() {
  if (!control_request_) return;
  control_runner_->sweep(control_request_->settings, {-1.0, 1.0, 0.05, 1});
}

void MainWindow::editControlSection(const std::function<void(app::ControlRequest&)>& change, const QString& what,
                                    int gesture_id) {
  if (!control_request_) return;
  app::ControlRequest r = *control_request_;
  change(r);
  app::Project edited = doc_.project();
  edited.control = app::controlSectionFrom(r, edited.control.value_or(app::ControlSection{}));
  // The section's own validation (ranges, workpiece) before the edit is pushed.
  try {
    app::validateProject(edited);
    app::controlRequestFromProject(edited);
  } catch (const std::exception& e) {
    showError(what, e.what());
    refreshControl({});  // the editors show the project's values again
    return;
  }
  const QString error = doc_.applyEdit(edited, what, gesture_id);
  if (!error.isEmpty()) showError(what, error);
}

}  // namespace mx::gui
