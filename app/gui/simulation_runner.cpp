#include "simulation_runner.h"

#include <algorithm>
#include <exception>

#include "core/cancellation.h"
#include "simulation/time_domain_simulator.h"
#include "simulation_job.h"

namespace mx::gui {

SimulationRunner::SimulationRunner(QThreadPool* enginePool, QObject* parent)
    : QObject(parent), pool_(enginePool), channel_(this) {
  qRegisterMetaType<mx::gui::SimulationChunkData>();
  qRegisterMetaType<mx::gui::SimulationSummary>();
}

// A job still queued or running keeps its copied inputs and posts nothing more (channel_); calls already
// posted are discarded with this object.
SimulationRunner::~SimulationRunner() {
  cancel();
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
  channel_.start(pool, [this, input = std::move(input), generation, cancel = cancel_](const EngineReply& reply) {
    const ChunkSink sink = [&](SimulationChunkData&& chunk) {
      reply([this, generation, chunk = std::move(chunk)] { deliverChunk(generation, chunk); });
    };
    try {
      SimulationSummary summary = runSimulationJob(input, *cancel, sink);
      reply(
          [this, generation, summary = std::move(summary)] { deliverEnd(generation, Outcome::Finished, summary, {}); });
    } catch (const Cancelled&) {
      reply([this, generation] { deliverEnd(generation, Outcome::Cancelled, {}, {}); });
    } catch (const std::exception& e) {
      reply([this, generation, message = QString::fromStdString(e.what())] {
        deliverEnd(generation, Outcome::Failed, {}, message);
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
