#include "engine_runner.h"

#include <QPointer>
#include <QtConcurrent>

namespace mx::gui {

EngineRunner::EngineRunner(QObject* parent) : QObject(parent) {
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

bool EngineRunner::busy() const {
  return running_ > 0;
}

quint64 EngineRunner::submitLobes(LobeJobInput input) {
  cancelAll();
  cancel_ = std::make_shared<std::atomic<bool>>(false);
  const quint64 generation = ++generation_;
  auto cancel = cancel_;
  auto* watcher = new QFutureWatcher<LobeJobResult>(this);
  connect(watcher, &QFutureWatcher<LobeJobResult>::finished, this, [this, watcher, generation] {
    const LobeJobResult result = watcher->result();
    watcher->deleteLater();
    if (--running_ == 0) emit busyChanged(false);
    if (generation == generation_) emit lobesReady(result);  // stale results are dropped
  });
  if (running_++ == 0) emit busyChanged(true);
  // Progress crosses to the GUI thread queued, at most once per percent.
  QPointer<EngineRunner> self(this);
  auto last = std::make_shared<std::atomic<int>>(-1);
  auto progress = [self, generation, last](double f) {
    const int percent = static_cast<int>(f * 100.0);
    if (percent == last->exchange(percent)) return;
    QMetaObject::invokeMethod(
        self.data(),
        [self, generation, f] {
          if (self && generation == self->generation_) emit self->lobeProgress(f);
        },
        Qt::QueuedConnection);
  };
  watcher->setFuture(QtConcurrent::run(&pool_, [input = std::move(input), generation, cancel, progress] {
    return runLobeJob(input, generation, *cancel, progress);
  }));
  return generation;
}

}  // namespace mx::gui
