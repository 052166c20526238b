#include "learning_client.h"

namespace mx::gui {

LearningClient::LearningClient(QObject* parent) : QObject(parent), worker_(new LearningWorker), channel_(this) {
  thread_.setObjectName("learningDatabase");
  worker_->moveToThread(&thread_);
  test_pool_.setMaxThreadCount(4);  // tests of unreachable servers may overlap
  // Every crossing between the two threads goes through handOverMutex() (engine_channel.h), so that
  // ThreadSanitizer sees the order Qt's queues give it.
  connect(worker_, &LearningWorker::recorded, this, [this](quint64 generation, qint64 id, const QString& location) {
    detail::enterHandOver();
    answered();
    emit recorded(generation, id, location);
  });
  connect(worker_, &LearningWorker::historyLoaded, this,
          [this](quint64 generation, const LearningHistoryResult& result) {
            detail::enterHandOver();
            answered();
            if (generation == history_generation_) emit historyLoaded(generation, result);
          });
  connect(worker_, &LearningWorker::recordFailed, this, [this](quint64 generation, const QString& message) {
    detail::enterHandOver();
    answered();
    emit recordFailed(generation, message);
  });
  connect(worker_, &LearningWorker::historyFailed, this, [this](quint64 generation, const QString& message) {
    detail::enterHandOver();
    answered();
    if (generation == history_generation_) emit historyFailed(generation, message);
  });
  thread_.start();
}

LearningClient::~LearningClient() {
  // Queued before the quit, so the thread closes the connection it opened; the hand-overs around
  // close() order its writes before the delete below.
  postHandOver(worker_, [worker = worker_] {
    worker->close();
    detail::enterHandOver();
  });
  thread_.quit();
  thread_.wait();
  detail::enterHandOver();
  delete worker_;
  test_pool_.waitForDone();  // answers of finished tests are dropped with the channel
}

quint64 LearningClient::record(const QString& location, const app::LearningRecord& record) {
  const quint64 generation = ++generation_;
  if (pending_++ == 0) emit idleChanged(false);
  postHandOver(worker_,
               [worker = worker_, generation, location, record] { worker->record(generation, location, record); });
  return generation;
}

quint64 LearningClient::loadHistory(const QString& location, const LearningHistoryRequest& request) {
  const quint64 generation = ++generation_;
  history_generation_ = generation;
  if (pending_++ == 0) emit idleChanged(false);
  postHandOver(worker_, [worker = worker_, generation, location, request] {
    worker->loadHistory(generation, location, request);
  });
  return generation;
}

quint64 LearningClient::testConnection(const QString& location) {
  const quint64 generation = ++generation_;
  test_generation_ = generation;
  channel_.start(&test_pool_, [this, generation, location](const EngineReply& reply) {
    const LearningConnectionReport report = testLearningConnection(location);
    reply([this, generation, report] {
      if (generation == test_generation_) emit tested(generation, report.ok, report.text);
    });
  });
  return generation;
}

void LearningClient::answered() {
  if (--pending_ == 0) emit idleChanged(true);
}

}  // namespace mx::gui
