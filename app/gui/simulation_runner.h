#pragma once
// Runs the time-domain simulation of a picked operating point on the engine thread (the one-thread
// pool of EngineRunner). Each submission copies its inputs, gets a generation id and cancels the
// running one (atomic flag, polled every revolution). A copy of every revolution's samples reaches the
// GUI thread through a queued call while the run goes on; chunks and results of an older generation
// are dropped before they are emitted.
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <atomic>
#include <memory>

#include "engine_channel.h"
#include "model/milling_setup.h"
#include "simulation/simulation_types.h"
#include "simulation_data.h"

namespace mx::gui {

class SimulationRunner : public QObject {
  Q_OBJECT
 public:
  static constexpr int kDefaultRegenerativePasses = 4;

  explicit SimulationRunner(QThreadPool* enginePool, QObject* parent = nullptr);
  ~SimulationRunner() override;

  // Cancels the running simulation and queues this one. options.on_chunk is replaced (the runner
  // streams the chunks) and options.regenerative_passes by regenerativePasses(). A limit <= 0 means
  // none; max_spindle_rev_per_s <= 0 or inf leaves the suggested speed unbounded above.
  quint64 submit(const mx::MillingSetup& setup, const mx::OperatingPoint& point, const mx::SimulationOptions& options,
                 double spindle_power_limit_w, double max_spindle_rev_per_s);
  // Cancels the running simulation; nothing more of it is emitted.
  void cancel();

  // Surface memory K of the live view (default 4: bounded chatter amplitude; K = 1 is eq. 7 as printed).
  void setRegenerativePasses(int passes);
  int regenerativePasses() const { return regenerative_passes_; }

  bool busy() const { return running_ > 0; }
  quint64 currentGeneration() const { return generation_; }

 signals:
  void chunkReady(quint64 generation, const mx::gui::SimulationChunkData& chunk);
  void finished(quint64 generation, const mx::gui::SimulationSummary& summary);
  void failed(quint64 generation, const QString& message);
  void progress(double fraction);  // of the current generation, in [0, 1]
  void busyChanged(bool busy);

 private:
  enum class Outcome { Finished, Failed, Cancelled };

  void deliverChunk(quint64 generation, const SimulationChunkData& chunk);
  void deliverEnd(quint64 generation, Outcome outcome, const SimulationSummary& summary, const QString& message);

  QThreadPool* pool_;
  EngineChannel channel_;
  std::shared_ptr<std::atomic<bool>> cancel_;
  quint64 generation_ = 0;
  int running_ = 0;
  int regenerative_passes_ = kDefaultRegenerativePasses;
};

}  // namespace mx::gui
