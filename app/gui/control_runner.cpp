#include "control_runner.h"

#include "core/cancellation.h"

namespace mx::gui {

ControlRunner::ControlRunner(QThreadPool* engine_pool, QObject* parent)
    : QObject(parent), pool_(engine_pool), channel_(this) {
  qRegisterMetaType<mx::gui::ControlOutcome>();
  qRegisterMetaType<mx::gui::SweepOutcome>();
}

ControlRunner::~ControlRunner() {
  cancel();
}

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

// Runs `work(job)` on the engine pool with a fresh cancel flag (the previous one of the same kind is
// set), then delivers the outcome on the GUI thread when it is still the newest of its kind.
template <class Outcome, class Work, class Deliver>
quint64 ControlRunner::launch(std::shared_ptr<std::atomic<bool>>& cancel, quint64& generation_counter, Work work,
                              Deliver deliver) {
  if (cancel) cancel->store(true);
  cancel = std::make_shared<std::atomic<bool>>(false);
  const quint64 generation = ++generation_counter;
  started();
  channel_.start(pool_,
                 [this, work, generation, flag = cancel, &generation_counter, deliver](const EngineReply& reply) {
                   Outcome out;
                   out.generation = generation;
                   JobControl job;
                   job.cancel = flag.get();
                   try {
                     work(job, out);
                   } catch (const Cancelled&) {
                     out.error = "cancelled";
                   } catch (const std::exception& e) {
                     out.error = QString::fromStdString(e.what());
                   }
                   reply([this, out = std::move(out), &generation_counter, deliver] {
                     stopped();
                     if (out.generation == generation_counter) deliver(out);
                   });
                 });
  return generation;
}

quint64 ControlRunner::run(const AdaptiveControlSettings& settings) {
  return launch<ControlOutcome>(
      run_cancel_, run_generation_,
      [settings](const JobControl& job, ControlOutcome& out) {
        out.threshold_beta = closedLoopZeroThreshold(settings);
        out.result = std::make_shared<const ClosedLoopResult>(simulateAdaptiveForceControl(settings, job));
      },
      [this](const ControlOutcome& o) { emit finished(o); });
}

quint64 ControlRunner::sweep(const AdaptiveControlSettings& settings, const BetaSweepSettings& sweep) {
  // One engine thread: the sweep runs single-threaded so that the GUI's pool stays one thread.
  BetaSweepSettings s = sweep;
  s.threads = 1;
  return launch<SweepOutcome>(
      sweep_cancel_, sweep_generation_,
      [settings, s](const JobControl& job, SweepOutcome& out) {
        out.threshold_beta = closedLoopZeroThreshold(settings);
        out.result = std::make_shared<const BetaSweepResult>(sweepBeta(settings, s, job));
      },
      [this](const SweepOutcome& o) { emit sweepFinished(o); });
}

}  // namespace mx::gui
