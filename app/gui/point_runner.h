#pragma once
// The readout thread: evaluates the operating point (PointEvaluator) off the GUI thread. It is a
// thread of its own, not the engine pool, so that a drag's readouts never wait behind lobes or a study.
// While one evaluation runs, only the latest request waits: a fast drag costs at most one evaluation
// behind the pointer, and the last answer is always that of the last request. The readout comes back
// first; the power-limit curve (a table of static cuts over the depths) follows in a second answer,
// and is left to the queued request when a newer one arrived meanwhile.
#include <QObject>
#include <QThreadPool>
#include <QVector>
#include <atomic>
#include <memory>
#include <optional>

#include "document/project_document.h"
#include "engine_channel.h"
#include "point_evaluator.h"

namespace mx::gui {

struct PointJob {
  std::shared_ptr<const PointEvaluator> evaluator;
  int tool = -1;
  app::PickedPoint point;
  bool with_power_limit = false;  // also the power-limit curve at the point's feed
};

struct PointJobResult {
  quint64 generation = 0;
  std::shared_ptr<const PointEvaluator> evaluator;  // the one that answered
  int tool = -1;
  app::PickedPoint point;
  std::optional<widgets::PointReadout> readout;   // the first answer
  std::optional<QVector<double>> power_limit_mm;  // the second answer (with_power_limit only)
};

class PointRunner : public QObject {
  Q_OBJECT
 public:
  explicit PointRunner(QObject* parent = nullptr);
  ~PointRunner() override;

  // Queues the job (replacing a queued one, whose power-limit request it inherits); returns its
  // generation, larger than every earlier one.
  quint64 submit(PointJob job);
  quint64 latestGeneration() const { return generation_; }
  bool busy() const { return busy_; }

 signals:
  void evaluated(const mx::gui::PointJobResult& result);

 private:
  void run(PointJob job, quint64 generation);
  void finished(bool power_limit_left);

  QThreadPool pool_;  // declared before the channel: the channel is closed before the pool is joined
  EngineChannel channel_;
  std::shared_ptr<std::atomic<quint64>> latest_ = std::make_shared<std::atomic<quint64>>(0);
  std::optional<std::pair<PointJob, quint64>> queued_;
  quint64 generation_ = 0;
  bool busy_ = false;
};

}  // namespace mx::gui

Q_DECLARE_METATYPE(mx::gui::PointJobResult)
