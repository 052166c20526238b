#include "control_runner.h"

#include <QFutureWatcher>
#include <QtConcurrent>

#include "control/force_plant.h"
#include "control/zero_threshold.h"
#include "model/job_control.h"

namespace mx::gui {

ControlRunner::ControlRunner(QThreadPool* engine_pool, QObject* parent) : QObject(parent), pool_(engine_pool) {
  qRegisterMetaType<mx::gui::ControlOutcome>();
  qRegisterMetaType<mx::gui::SweepOutcome>();
}

ControlRunner::~ControlRunner() { cancel(); }

void ControlRunner::cancel() {
  if (run_cancel_) run_cancel_->store(true);
  if (sweep_cancel_) sweep_cancel_->store(true);
}

void ControlRunner::started() {
  if (running_++ == 0) emit busyChanged(true);
}

void ControlRunner::stopped() {
  if (--running_ == 0) emit busyChanged(false);
}

double ControlRunner::zeroThreshold(const AdaptiveControlSettings& s) {
  if (s.workpiece.steps.empty()) return -1.0;
  const double depth = s.workpiece.steps.front().depth_m > 0.0 ? s.workpiece.steps.front().depth_m : 1e-3;
  return unstableZeroThreshold(makeForcePlant(s.process, depth).stateSpace(), 1.0 / s.process.spindle_rev_s)
      .threshold_beta;
}

quint64 ControlRunner::run(const AdaptiveControlSettings& settings) {
  if (run_cancel_) run_cancel_->store(true);
  run_cancel_ = std::make_shared<std::atomic<bool>>(false);
  const quint64 generation = ++run_generation_;
  auto* watcher = new QFutureWatcher<ControlOutcome>(this);
  connect(watcher, &QFutureWatcher<ControlOutcome>::finished, this, [this, watcher] {
    const ControlOutcome outcome = watcher->result();
    watcher->deleteLater();
    stopped();
    if (outcome.generation == run_generation_) emit finished(outcome);
  });
  started();
  watcher->setFuture(QtConcurrent::run(pool_, [settings, generation, cancel = run_cancel_] {
    ControlOutcome out;
    out.generation = generation;
    JobControl job;
    job.cancel = cancel.get();
    try {
      out.threshold_beta = zeroThreshold(settings);
      out.result = std::make_shared<const ClosedLoopResult>(simulateAdaptiveForceControl(settings, job));
    } catch (const Cancelled&) {
      out.error = "cancelled";
    } catch (const std::exception& e) {
      out.error = QString::fromStdString(e.what());
    }
    return out;
  }));
  return generation;
}

quint64 ControlRunner::sweep(const AdaptiveControlSettings& settings, const BetaSweepSettings& sweep) {
  if (sweep_cancel_) sweep_cancel_->store(true);
  sweep_cancel_ = std::make_shared<std::atomic<bool>>(false);
  const quint64 generation = ++sweep_generation_;
  auto* watcher = new QFutureWatcher<SweepOutcome>(this);
  connect(watcher, &QFutureWatcher<SweepOutcome>::finished, this, [this, watcher] {
    const SweepOutcome outcome = watcher->result();
    watcher->deleteLater();
    stopped();
    if (outcome.generation == sweep_generation_) emit sweepFinished(outcome);
  });
  started();
  // One engine thread: the sweep itself runs single-threaded so that the GUI's pool stays one thread.
  BetaSweepSettings s = sweep;
  s.threads = 1;
  watcher->setFuture(QtConcurrent::run(pool_, [settings, s, generation, cancel = sweep_cancel_] {
    SweepOutcome out;
    out.generation = generation;
    JobControl job;
    job.cancel = cancel.get();
    try {
      out.threshold_beta = zeroThreshold(settings);
      out.result = std::make_shared<const BetaSweepResult>(sweepBeta(settings, s, job));
    } catch (const Cancelled&) {
      out.error = "cancelled";
    } catch (const std::exception& e) {
      out.error = QString::fromStdString(e.what());
    }
    return out;
  }));
  return generation;
}

}  // namespace mx::gui
