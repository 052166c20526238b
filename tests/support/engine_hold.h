#pragma once
// Test helper: holds the engine thread (the GUI's one-thread pool) so that the jobs submitted meanwhile
// queue behind the hold. runQueuedJobs() then lets them run to their end while the GUI thread takes none
// of their results: they wait in its event queue, behind whatever the test does next, as the result of
// a job that ends just after an edit would.
#include <QSemaphore>
#include <QThreadPool>

namespace mx::test {

class EngineHold {
 public:
  explicit EngineHold(QThreadPool* pool) : pool_(pool) {
    pool_->start([this] { released_.acquire(); });
  }
  ~EngineHold() {
    release();
    pool_->waitForDone();
  }
  EngineHold(const EngineHold&) = delete;
  EngineHold& operator=(const EngineHold&) = delete;

  // Releases the engine thread and waits, without an event loop, until every queued job has ended.
  bool runQueuedJobs(int timeout_ms = 120000) {
    release();
    return pool_->waitForDone(timeout_ms);
  }

 private:
  void release() {
    if (released_once_) return;
    released_once_ = true;
    released_.release();
  }

  QThreadPool* pool_;
  QSemaphore released_;
  bool released_once_ = false;
};

}  // namespace mx::test
