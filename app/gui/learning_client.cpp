#include "learning_client.h"

#include <QMetaObject>

namespace mx::gui {

LearningClient::LearningClient(QObject* parent) : QObject(parent), worker_(new LearningWorker), channel_(this) {
  thread_.setObjectName("learningDatabase");
  worker_->moveToThread(&thread_);
  test_pool_.setMaxThreadCount(4);  // tests of unreachable servers may overlap
  connect(worker_, &LearningWorker::recorded, this, [this](quint64 generation, qint64 id, const QString& location) {
    answered();
    emit recorded(generation, id, location);
  });
  connect(worker_, &LearningWorker::historyLoaded, this,
          [this](quint64 generation, const LearningHistoryResult& result) {
            answered();
            if (generation == history_generation_) emit historyLoaded(generation, result);
          });
  connect(worker_, &LearningWorker::recordFailed, this, [this](quint64 generation, const QString& message) {
    answered();
    emit recordFailed(generation, message);
  });
  connect(worker_, &LearningWorker::historyFailed, this, [this](quint64 generation, const QString& message) {
    answered();
    if (generation == history_generation_) emit historyFailed(generation, message);
  });
  thread_.start();
}

LearningClient::~LearningClient() {
  QMetaObject::invokeMethod(
      worker_, [worker = worker_] { worker->close(); }, Qt::BlockingQueuedConnection);
  thread_.quit();
  thread_.wait();
  delete worker_;
  test_pool_.waitForDone();  // answers of finished tests are dropped with the channel
}

quint64 LearningClient::record(const QString& location, const app::LearningRecord& record) {
  const quint64 generation = ++generation_;
  if (pending_++ == 0) emit idleChanged(false);
  QMetaObject::invokeMethod(
      worker_, [worker = worker_, generation, location, record] { worker->record(generation, location, record); },
      Qt::QueuedConnection);
  return generation;
}

quint64 LearningClient::loadHistory(const QString& location, const LearningHistoryRequest& request) {
  const quint64 generation = ++generation_;
  history_generation_ = generation;
  if (pending_++ == 0) emit idleChanged(false);
  QMetaObject::invokeMethod(
      worker_,
      [worker = worker_, generation, location, request] { worker->loadHistory(generation, location, request); },
      Qt::QueuedConnection);
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
