#pragma once
// The Pareto expert system behind the GUI (Pareto paper, modules V-VII). On the engine thread: the ParetoStudy of the
// project (admissible grid of pareto.tool, objective table, non-dominated set, operator rules) and
// the weights that support each front point, once per change of the project's engine inputs. On the
// GUI thread: choose() for the current weights and requirement (one pass over the table,
// milliseconds). Stale results (an older generation) are dropped.
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <memory>
#include <optional>
#include <vector>

#include "document/project.h"
#include "engine_channel.h"
#include "services/pareto_study.h"

namespace mx::gui {

struct ParetoOutcome {
  quint64 generation = 0;
  std::shared_ptr<const app::ParetoStudy> study;            // null on error
  std::vector<std::optional<ParetoWeights>> front_weights;  // aligned with study->front()
  QString error;
};

class ParetoRunner : public QObject {
  Q_OBJECT
 public:
  ParetoRunner(QThreadPool* engine_pool, QObject* parent = nullptr);

  // Builds the study of a copy of `project` on the engine thread.
  quint64 build(const app::Project& project);
  // Drops the current study (a project without a "pareto" section); pending builds become stale.
  void clear();
  // Pending builds become stale (the project they were for has changed); the current study stays until
  // the next build replaces it.
  void dropPending();

  const std::shared_ptr<const app::ParetoStudy>& study() const { return study_; }
  const std::vector<std::optional<ParetoWeights>>& frontWeights() const { return front_weights_; }
  bool busy() const { return running_ > 0; }

 signals:
  void studyReady(const QString& error);  // "" on success
  void busyChanged(bool busy);

 private:
  QThreadPool* pool_;
  EngineChannel channel_;
  std::shared_ptr<const app::ParetoStudy> study_;
  std::vector<std::optional<ParetoWeights>> front_weights_;
  quint64 generation_ = 0;
  int running_ = 0;
};

}  // namespace mx::gui
