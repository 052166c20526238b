#include "pareto_runner.h"

#include <QFutureWatcher>
#include <QtConcurrent>

namespace mx::gui {

ParetoRunner::ParetoRunner(QThreadPool* engine_pool, QObject* parent) : QObject(parent), pool_(engine_pool) {}

quint64 ParetoRunner::build(const app::Project& project) {
  const quint64 generation = ++generation_;
  auto* watcher = new QFutureWatcher<ParetoOutcome>(this);
  connect(watcher, &QFutureWatcher<ParetoOutcome>::finished, this, [this, watcher] {
    ParetoOutcome outcome = watcher->result();
    watcher->deleteLater();
    if (--running_ == 0) emit busyChanged(false);
    if (outcome.generation != generation_) return;  // stale
    study_ = std::move(outcome.study);
    front_weights_ = std::move(outcome.front_weights);
    emit studyReady(outcome.error);
  });
  if (running_++ == 0) emit busyChanged(true);
  watcher->setFuture(QtConcurrent::run(pool_, [project, generation]() {
    ParetoOutcome outcome;
    outcome.generation = generation;
    try {
      auto study = std::make_shared<const app::ParetoStudy>(project);
      outcome.front_weights = study->supportingWeights();
      outcome.study = std::move(study);
    } catch (const std::exception& e) {
      outcome.error = QString::fromStdString(e.what());
    }
    return outcome;
  }));
  return generation;
}

void ParetoRunner::clear() {
  ++generation_;
  study_.reset();
  front_weights_.clear();
}

}  // namespace mx::gui
