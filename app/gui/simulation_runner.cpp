#include "simulation_runner.h"

#include <QMetaObject>
#include <algorithm>
#include <exception>

#include "core/cancellation.h"
#include "simulation/time_domain_simulator.h"
#include "simulation_job.h"

namespace mx::gui {

namespace {
// Runs `call` on the runner's (GUI) thread, if the runner still exists; queued, in posting order.
template <class Channel, class Call>
void post(const std::shared_ptr<Channel>& channel, Call&& call) {
  std::lock_guard lock(channel->mutex);
  if (auto* runner = channel->runner)
    QMetaObject::invokeMethod(
        runner, [runner, call = std::forward<Call>(call)]() mutable { call(runner); }, Qt::QueuedConnection);
}
}  // namespace

SimulationRunner::SimulationRunner(QThreadPool* enginePool, QObject* parent)
    : QObject(parent), pool_(enginePool), channel_(std::make_shared<Channel>()) {
  channel_->runner = this;
  qRegisterMetaType<mx::gui::SimulationChunkData>();
  qRegisterMetaType<mx::gui::SimulationSummary>();
}

SimulationRunner::~SimulationRunner() {
  cancel();
  // A job still queued or running keeps its copied inputs and posts nothing more; calls already posted
  // are discarded with this object.
  std::lock_guard lock(channel_->mutex);
  channel_->runner = nullptr;
}

void SimulationRunner::setRegenerativePasses(int passes) {
  regenerative_passes_ = std::clamp(passes, 1, kMaxRegenerativePasses);
}

void SimulationRunner::cancel() {
  if (cancel_) cancel_->store(true);
  cancel_.reset();
  ++generation_;  // whatever is still in flight is stale
}

quint64 SimulationRunner::submit(const mx::MillingSetup& setup, const mx::OperatingPoint& point,
                                 const mx::SimulationOptions& options, double spindle_power_limit_w,
                                 double max_spindle_rev_per_s) {
  cancel();
  cancel_ = std::make_shared<std::atomic<bool>>(false);
  const quint64 generation = generation_;

  SimulationJobInput input;
  input.setup = setup;
  input.point = point;
  input.options = options;
  input.options.on_chunk = nullptr;
  input.options.regenerative_passes = regenerative_passes_;
  input.spindle_power_limit_w = spindle_power_limit_w;
  input.max_spindle_rev_per_s = max_spindle_rev_per_s;

  if (running_++ == 0) emit busyChanged(true);
  emit progress(0.0);
  QThreadPool* pool = pool_ ? pool_ : QThreadPool::globalInstance();
  pool->start([input = std::move(input), generation, cancel = cancel_, channel = channel_] {
    const ChunkSink sink = [&](SimulationChunkData&& chunk) {
      post(channel,
           [generation, chunk = std::move(chunk)](SimulationRunner* r) { r->deliverChunk(generation, chunk); });
    };
    try {
      SimulationSummary summary = runSimulationJob(input, *cancel, sink);
      post(channel, [generation, summary = std::move(summary)](SimulationRunner* r) {
        r->deliverEnd(generation, Outcome::Finished, summary, {});
      });
    } catch (const Cancelled&) {
      post(channel, [generation](SimulationRunner* r) { r->deliverEnd(generation, Outcome::Cancelled, {}, {}); });
    } catch (const std::exception& e) {
      post(channel, [generation, message = QString::fromStdString(e.what())](SimulationRunner* r) {
        r->deliverEnd(generation, Outcome::Failed, {}, message);
      });
    }
  });
  return generation;
}

void SimulationRunner::deliverChunk(quint64 generation, const SimulationChunkData& chunk) {
  if (generation != generation_) return;  // stale
  emit chunkReady(generation, chunk);
  if (chunk.revolutions > 0) emit progress(static_cast<double>(chunk.revolution) / chunk.revolutions);
}

void SimulationRunner::deliverEnd(quint64 generation, Outcome outcome, const SimulationSummary& summary,
                                  const QString& message) {
  const bool current = generation == generation_;
  if (current) cancel_.reset();
  if (--running_ == 0) emit busyChanged(false);
  if (!current) return;  // stale (or cancelled): dropped
  if (outcome == Outcome::Finished) {
    emit progress(1.0);
    emit finished(generation, summary);
  } else if (outcome == Outcome::Failed) {
    emit failed(generation, message);
  }
}

}  // namespace mx::gui
