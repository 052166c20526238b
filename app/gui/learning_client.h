#pragma once
// The GUI's road to the Rule 14 learning database: records and history queries go in order to the
// LearningWorker on the dedicated learning thread, connection tests to a small pool of their own (a
// test of an unreachable server waits its connect_timeout and must hold up neither the records nor a
// newer test). Answers come back as queued signals tagged with a generation id: every record answers,
// a newer history query or connection test makes the older one's answer stale, and it is dropped.
#include <QObject>
#include <QString>
#include <QThread>
#include <QThreadPool>

#include "engine_channel.h"
#include "learning_worker.h"

namespace mx::gui {

class LearningClient : public QObject {
  Q_OBJECT
 public:
  explicit LearningClient(QObject* parent = nullptr);
  ~LearningClient() override;  // waits for the request in progress, then closes the connection

  quint64 record(const QString& location, const app::LearningRecord& record);  // recorded() or recordFailed()
  quint64 loadHistory(const QString& location,
                      const LearningHistoryRequest& request);  // historyLoaded() or historyFailed()
  quint64 testConnection(const QString& location);             // tested()
  // No record or history query is waiting for its answer (connection tests aside).
  bool idle() const { return pending_ == 0; }

 signals:
  void recorded(quint64 generation, qint64 id, const QString& location);
  void recordFailed(quint64 generation, const QString& message);
  void historyLoaded(quint64 generation, const mx::gui::LearningHistoryResult& result);
  void historyFailed(quint64 generation, const QString& message);
  void tested(quint64 generation, bool ok, const QString& text);
  void idleChanged(bool idle);

 private:
  void answered();

  QThread thread_;
  LearningWorker* worker_;
  QThreadPool test_pool_;
  EngineChannel channel_;
  quint64 generation_ = 0;
  quint64 history_generation_ = 0;
  quint64 test_generation_ = 0;
  int pending_ = 0;
};

}  // namespace mx::gui
