#pragma once
// The engine thread: a one-thread pool that runs copied-input jobs. Each submission gets a
// generation id and an atomic cancel flag; a newer submission cancels the older one, and stale
// results are dropped before they reach the GUI (delivered through queued signals).
#include <QObject>
#include <QThreadPool>
#include <atomic>
#include <memory>

#include "engine_channel.h"
#include "lobe_job.h"

namespace mx::gui {

class EngineRunner : public QObject {
  Q_OBJECT
 public:
  explicit EngineRunner(QObject* parent = nullptr);
  ~EngineRunner() override;

  quint64 submitLobes(LobeJobInput input);
  // Cancels the running job; it still reports that it was cancelled.
  void cancelAll();
  // Cancels the running job and drops whatever it still delivers: the project it was for has changed.
  void dropPending();
  bool busy() const;
  // The engine thread (a one-thread pool): every job of the GUI runs here, never on the GUI thread.
  QThreadPool* pool() { return &pool_; }

 signals:
  void lobesReady(const mx::gui::LobeJobResult& result);
  void lobeProgress(double fraction);
  void busyChanged(bool busy);

 private:
  QThreadPool pool_;
  EngineChannel channel_;
  quint64 generation_ = 0;
  std::shared_ptr<std::atomic<bool>> cancel_;
  int running_ = 0;
};

}  // namespace mx::gui
