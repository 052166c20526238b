#include "engine_runner.h"

#include <utility>

namespace mx::gui {

EngineRunner::EngineRunner(QObject* parent) : QObject(parent), channel_(this) {
  pool_.setMaxThreadCount(1);
  qRegisterMetaType<mx::gui::LobeJobResult>();
}

EngineRunner::~EngineRunner() {
  cancelAll();
  pool_.waitForDone();
}

void EngineRunner::cancelAll() {
  if (cancel_) cancel_->store(true);
}

void EngineRunner::dropPending() {
  cancelAll();
  ++generation_;
}

bool EngineRunner::busy() const {
  return running_ > 0;
}

quint64 EngineRunner::submitLobes(LobeJobInput input) {
  cancelAll();
  cancel_ = std::make_shared<std::atomic<bool>>(false);
  const quint64 generation = ++generation_;
  auto cancel = cancel_;
  if (running_++ == 0) emit busyChanged(true);
  channel_.start(&pool_, [this, input = std::move(input), generation, cancel](const EngineReply& reply) {
    // Progress crosses to the GUI thread queued, at most once per percent.
    int last_percent = -1;
    auto progress = [this, generation, &last_percent, &reply](double f) {
      const int percent = static_cast<int>(f * 100.0);
      if (percent == std::exchange(last_percent, percent)) return;
      reply([this, generation, f] {
        if (generation == generation_) emit lobeProgress(f);
      });
    };
    LobeJobResult result = runLobeJob(input, generation, *cancel, progress);
    reply([this, generation, result = std::move(result)] {
      if (--running_ == 0) emit busyChanged(false);
      if (generation == generation_) emit lobesReady(result);  // stale results are dropped
    });
  });
  return generation;
}

}  // namespace mx::gui
