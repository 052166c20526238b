#pragma once
// The supervised face-milling run behind the supervisor view, on the engine thread: the
// Grafcet interpreter of the chosen chart, the modules and the process (runSupervision). The run is
// paced to `speed_factor` times real time (0: as fast as possible) so that the operator can press
// feed hold or chatter while it runs: those events are queued from the GUI thread and read by the run
// at its next scan. Progress arrives as chunks (new samples, situations, module records, events since
// the last chunk) through queued signals tagged with a generation id; stale ones are dropped.
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <QVector>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>

#include "engine_channel.h"
#include "grafcet/grafcet_chart.h"
#include "supervisor/supervision_run.h"

namespace mx::gui {

struct SupervisionChunk {
  quint64 generation = 0;
  std::vector<SupervisionSample> samples;
  std::vector<ActiveStepsRecord> steps;
  std::vector<ModuleActivityRecord> modules;
  std::vector<SupervisionEvent> events;
};

struct SupervisionOutcome {
  quint64 generation = 0;
  QString controller;
  std::shared_ptr<const SupervisionResult> result;  // null on error
  QString error;
};

class SupervisionRunner : public QObject {
  Q_OBJECT
 public:
  SupervisionRunner(QThreadPool* engine_pool, QObject* parent = nullptr);
  ~SupervisionRunner() override;

  // One live run (cancels a previous one).
  quint64 start(const SupervisionScenario& scenario, const GrafcetChart& chart, double speed_factor);
  // The three controllers one after another, as fast as possible (comparison).
  quint64 compare(const std::vector<std::pair<SupervisionScenario, GrafcetChart>>& runs);
  void stop();
  void inject(OperatorEventType type);  // into the running live run
  bool running() const { return running_ > 0; }

 signals:
  void chunkReady(const mx::gui::SupervisionChunk& chunk);
  void finished(const mx::gui::SupervisionOutcome& outcome);
  void compared(const mx::gui::SupervisionOutcome& outcome);  // one per controller
  void runningChanged(bool running);

 private:
  struct Live {
    std::mutex mutex;
    std::vector<OperatorEventType> pending;
    std::atomic<bool> cancel{false};
  };
  std::shared_ptr<Live> live_;
  std::shared_ptr<std::atomic<bool>> compare_cancel_;
  QThreadPool* pool_;
  EngineChannel channel_;
  quint64 generation_ = 0, compare_generation_ = 0;
  int running_ = 0;
};

}  // namespace mx::gui

Q_DECLARE_METATYPE(mx::gui::SupervisionChunk)
Q_DECLARE_METATYPE(mx::gui::SupervisionOutcome)
