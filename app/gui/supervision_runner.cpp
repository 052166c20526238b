#include "supervision_runner.h"

#include <QElapsedTimer>
#include <QThread>

#include "core/cancellation.h"
#include "grafcet/grafcet_interpreter.h"

namespace mx::gui {

namespace {

// One supervised run with its own interpreter; errors become the outcome's message.
SupervisionOutcome runOne(const SupervisionScenario& scenario, const GrafcetChart& chart, quint64 generation,
                          const JobControl& job) {
  SupervisionOutcome out;
  out.generation = generation;
  out.controller = QString::fromStdString(controllerName(scenario.controller));
  try {
    GrafcetInterpreter logic(chart);
    out.result = std::make_shared<const SupervisionResult>(runSupervision(scenario, logic, job));
  } catch (const Cancelled&) {
    out.error = "stopped";
  } catch (const std::exception& e) {
    out.error = QString::fromStdString(e.what());
  }
  return out;
}

}  // namespace

SupervisionRunner::SupervisionRunner(QThreadPool* engine_pool, QObject* parent)
    : QObject(parent), pool_(engine_pool), channel_(this) {
  qRegisterMetaType<mx::gui::SupervisionChunk>();
  qRegisterMetaType<mx::gui::SupervisionOutcome>();
}

SupervisionRunner::~SupervisionRunner() {
  stop();
}

void SupervisionRunner::stop() {
  if (live_) live_->cancel.store(true);
  if (compare_cancel_) compare_cancel_->store(true);
}

void SupervisionRunner::inject(OperatorEventType type) {
  if (!live_) return;
  std::lock_guard<std::mutex> lock(live_->mutex);
  live_->pending.push_back(type);
}

quint64 SupervisionRunner::start(const SupervisionScenario& scenario, const GrafcetChart& chart, double speed_factor) {
  if (live_) live_->cancel.store(true);
  live_ = std::make_shared<Live>();
  const quint64 generation = ++generation_;
  if (running_++ == 0) emit runningChanged(true);
  channel_.start(pool_,
                 [this, base = scenario, chart, speed_factor, generation, live = live_](const EngineReply& reply) {
                   SupervisionScenario run_scenario = base;
                   // Chunks: what the run added since the last one (checked every 50 ms of simulated time).
                   std::size_t n_samples = 0, n_steps = 0, n_modules = 0, n_events = 0;
                   QElapsedTimer wall;
                   wall.start();
                   run_scenario.progress_period_s = 0.05;
                   qint64 last_post_ms = -1000;
                   run_scenario.on_progress = [&](const SupervisionResult& r, double t_s) {
                     if (speed_factor > 0.0) {  // pace: simulated time <= speed x wall time
                       const double ahead_ms = t_s / speed_factor * 1e3 - static_cast<double>(wall.elapsed());
                       if (ahead_ms > 1.0) QThread::msleep(static_cast<unsigned long>(ahead_ms));
                     }
                     // At most one chunk per 40 ms of wall time: the GUI thread is never flooded, whatever the speed.
                     if (wall.elapsed() - last_post_ms < 40) return;
                     last_post_ms = wall.elapsed();
                     SupervisionChunk c;
                     c.generation = generation;
                     c.samples.assign(r.series.begin() + static_cast<std::ptrdiff_t>(n_samples), r.series.end());
                     c.steps.assign(r.steps.begin() + static_cast<std::ptrdiff_t>(n_steps), r.steps.end());
                     c.modules.assign(r.modules.begin() + static_cast<std::ptrdiff_t>(n_modules), r.modules.end());
                     c.events.assign(r.events.begin() + static_cast<std::ptrdiff_t>(n_events), r.events.end());
                     n_samples = r.series.size();
                     n_steps = r.steps.size();
                     n_modules = r.modules.size();
                     n_events = r.events.size();
                     reply([this, c = std::move(c)] { emit chunkReady(c); });
                   };
                   run_scenario.poll_events = [live](double t_s, std::vector<OperatorEvent>& events) {
                     std::lock_guard<std::mutex> lock(live->mutex);
                     for (OperatorEventType type : live->pending) events.push_back({t_s, type});
                     live->pending.clear();
                   };
                   JobControl job;
                   job.cancel = &live->cancel;
                   reply([this, o = runOne(run_scenario, chart, generation, job)] {
                     if (--running_ == 0) emit runningChanged(false);
                     if (o.generation == generation_) emit finished(o);
                   });
                 });
  return generation;
}

quint64 SupervisionRunner::compare(const std::vector<std::pair<SupervisionScenario, GrafcetChart>>& runs) {
  if (compare_cancel_) compare_cancel_->store(true);
  compare_cancel_ = std::make_shared<std::atomic<bool>>(false);
  const quint64 generation = ++compare_generation_;
  for (const auto& run : runs) {
    if (running_++ == 0) emit runningChanged(true);
    channel_.start(pool_, [this, run, generation, cancel = compare_cancel_](const EngineReply& reply) {
      JobControl job;
      job.cancel = cancel.get();
      reply([this, o = runOne(run.first, run.second, generation, job)] {
        if (--running_ == 0) emit runningChanged(false);
        if (o.generation == compare_generation_) emit compared(o);
      });
    });
  }
  return generation;
}

}  // namespace mx::gui
