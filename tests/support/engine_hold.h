#pragma once
// Test helper: holds the engine thread (the GUI's one-thread pool) so that the jobs submitted meanwhile
// queue behind the hold. runQueuedJobs() then lets them run to their end while the GUI thread takes none
// of their results: they wait in its event queue, behind whatever the test does next, as the result of
// a job that ends just after an edit would.
#include <QSemaphore>
#include <QString>
#include <QTest>
#include <QThreadPool>

#include "document/project.h"
#include "main_window.h"
#include "support/window_features.h"

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

// Applies `edited` with the engine thread held until `queued()` holds (the edit's debounced jobs are
// submitted), then runs those jobs to their end: their results wait for the test's next edit. Returns
// what failed, or "".
template <class Queued>
QString applyEditAndHoldItsResults(gui::MainWindow& window, const app::Project& edited, Queued queued) {
  EngineHold hold(contextOf(window)->enginePool());
  if (QString error = window.document()->applyEdit(edited, "held edit"); !error.isEmpty()) return error;
  if (!QTest::qWaitFor(queued, 5000)) return QStringLiteral("the edit's jobs were not submitted within 5 s");
  if (!hold.runQueuedJobs()) return QStringLiteral("the edit's jobs did not end within 120 s");
  return {};
}

}  // namespace mx::test
