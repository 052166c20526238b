#pragma once
// The GUI's one road to the engine pool and back. A job starts on the pool with copied inputs; its
// results come back as calls queued to the owner's (GUI) thread, and are dropped once the owner is gone.
//
// Every hand-over crosses one process-wide mutex (handOverMutex()): the GUI thread holds it while it
// gives a job to the pool, and the job takes it before it reads what it captured; the job holds it while
// it queues a call, and the call takes it before it reads its captures. Qt's queues already order these,
// but through futexes inside libQt6Core, which ThreadSanitizer does not see; the mutex makes the same
// order visible to it. It is a global so that taking it reads no memory of the hand-over itself, and it
// is held only for the duration of a queue operation.
#include <QMetaObject>
#include <QObject>
#include <QRunnable>
#include <QThreadPool>
#include <memory>
#include <mutex>
#include <utility>

namespace mx::gui {

std::mutex& handOverMutex();

namespace detail {
inline void enterHandOver() {
  std::lock_guard lock(handOverMutex());
}

struct ChannelState {
  QObject* owner = nullptr;  // null once the owner is gone; guarded by handOverMutex()
};

// A pool task of our own (not QRunnable::create): the job is stored before the hand-over and read after.
template <class Task>
class HandOverRunnable final : public QRunnable {
 public:
  explicit HandOverRunnable(Task task) : task_(std::move(task)) {}
  void run() override {
    enterHandOver();
    task_();
  }

 private:
  Task task_;
};
// Queues call() to `target`'s thread; the caller holds handOverMutex(), and the call takes it before
// it reads what it captured.
template <class Call>
void queueHandOver(QObject* target, Call call) {
  QMetaObject::invokeMethod(
      target,
      [call = std::move(call)]() mutable {
        enterHandOver();
        call();
      },
      Qt::QueuedConnection);
}

}  // namespace detail

// Queues call() to the thread of `target` (a QObject that outlives the call) across handOverMutex().
template <class Call>
void postHandOver(QObject* target, Call call) {
  std::lock_guard lock(handOverMutex());
  detail::queueHandOver(target, std::move(call));
}

// What a job holds to send calls back to the owner's thread; copyable, usable from any thread.
class EngineReply {
 public:
  explicit EngineReply(std::shared_ptr<detail::ChannelState> state) : state_(std::move(state)) {}

  // Queues call() to the owner's thread, in posting order; nothing happens when the owner is gone.
  template <class Call>
  void operator()(Call call) const {
    std::lock_guard lock(handOverMutex());
    if (state_->owner) detail::queueHandOver(state_->owner, std::move(call));
  }

 private:
  std::shared_ptr<detail::ChannelState> state_;
};

class EngineChannel {
 public:
  explicit EngineChannel(QObject* owner) : state_(std::make_shared<detail::ChannelState>()) { state_->owner = owner; }
  ~EngineChannel() {
    std::lock_guard lock(handOverMutex());
    state_->owner = nullptr;
  }
  EngineChannel(const EngineChannel&) = delete;
  EngineChannel& operator=(const EngineChannel&) = delete;

  // Runs job(reply) on `pool`; the job owns what it captured.
  template <class Job>
  void start(QThreadPool* pool, Job job) {
    auto task = [reply = EngineReply(state_), job = std::move(job)]() mutable { job(reply); };
    std::lock_guard lock(handOverMutex());
    pool->start(new detail::HandOverRunnable<decltype(task)>(std::move(task)));
  }

 private:
  std::shared_ptr<detail::ChannelState> state_;
};

}  // namespace mx::gui
