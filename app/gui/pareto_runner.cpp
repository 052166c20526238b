#include "pareto_runner.h"

namespace mx::gui {

ParetoRunner::ParetoRunner(QThreadPool* engine_pool, QObject* parent)
    : QObject(parent), pool_(engine_pool), channel_(this) {}

quint64 ParetoRunner::build(const app::Project& project) {
  const quint64 generation = ++generation_;
  if (running_++ == 0) emit busyChanged(true);
  channel_.start(pool_, [this, project, generation](const EngineReply& reply) {
    ParetoOutcome outcome;
    outcome.generation = generation;
    try {
      auto study = std::make_shared<const app::ParetoStudy>(project);
      outcome.front_weights = study->supportingWeights();
      outcome.study = std::move(study);
    } catch (const std::exception& e) {
      outcome.error = QString::fromStdString(e.what());
    }
    reply([this, outcome = std::move(outcome)]() mutable {
      if (--running_ == 0) emit busyChanged(false);
      if (outcome.generation != generation_) return;  // stale
      study_ = std::move(outcome.study);
      front_weights_ = std::move(outcome.front_weights);
      emit studyReady(outcome.error);
    });
  });
  return generation;
}

void ParetoRunner::clear() {
  dropPending();
  study_.reset();
  front_weights_.clear();
}

void ParetoRunner::dropPending() {
  ++generation_;
}

}  // namespace mx::gui
