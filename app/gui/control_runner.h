#pragma once
// The adaptive force controller behind the GUI's control view (2006 paper, section 4): one closed-loop run per beta
// (and the J_c(beta) sweep) on the engine thread. A new request cancels the running one through its
// atomic flag; results carry a generation id and stale ones are dropped.
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <atomic>
#include <memory>

#include "control/beta_sweep.h"
#include "control/closed_loop.h"
#include "engine_channel.h"

namespace mx::gui {

struct ControlOutcome {
  quint64 generation = 0;
  std::shared_ptr<const ClosedLoopResult> result;  // null on error
  double threshold_beta = -1.0;                    // a zero of H_beta leaves the unit circle below it
  QString error;
};

struct SweepOutcome {
  quint64 generation = 0;
  std::shared_ptr<const BetaSweepResult> result;
  double threshold_beta = -1.0;
  QString error;
};

class ControlRunner : public QObject {
  Q_OBJECT
 public:
  ControlRunner(QThreadPool* engine_pool, QObject* parent = nullptr);
  ~ControlRunner() override;

  quint64 run(const AdaptiveControlSettings& settings);
  quint64 sweep(const AdaptiveControlSettings& settings, const BetaSweepSettings& sweep);
  void cancel();
  bool busy() const { return running_ > 0; }

 signals:
  void finished(const mx::gui::ControlOutcome& outcome);
  void sweepFinished(const mx::gui::SweepOutcome& outcome);
  void busyChanged(bool busy);

 private:
  void started();
  void stopped();
  template <class Outcome, class Work, class Deliver>
  quint64 launch(std::shared_ptr<std::atomic<bool>>& cancel, quint64& generation_counter, Work work, Deliver deliver);

  QThreadPool* pool_;
  EngineChannel channel_;
  std::shared_ptr<std::atomic<bool>> run_cancel_, sweep_cancel_;
  quint64 run_generation_ = 0, sweep_generation_ = 0;
  int running_ = 0;
};

}  // namespace mx::gui

Q_DECLARE_METATYPE(mx::gui::ControlOutcome)
Q_DECLARE_METATYPE(mx::gui::SweepOutcome)
