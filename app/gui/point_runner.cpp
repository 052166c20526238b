#include "point_runner.h"

#include <utility>

namespace mx::gui {

PointRunner::PointRunner(QObject* parent) : QObject(parent), channel_(this) {
  qRegisterMetaType<mx::gui::PointJobResult>();
  pool_.setMaxThreadCount(1);
}

PointRunner::~PointRunner() {
  pool_.waitForDone();
}

quint64 PointRunner::submit(PointJob job) {
  const quint64 generation = ++generation_;
  if (busy_)
    queued_.emplace(std::move(job), generation);
  else
    run(std::move(job), generation);
  return generation;
}

void PointRunner::run(PointJob job, quint64 generation) {
  busy_ = true;
  channel_.start(&pool_, [this, job = std::move(job), generation](const EngineReply& reply) {
    PointJobResult result;
    result.generation = generation;
    result.evaluator = job.evaluator;
    result.tool = job.tool;
    result.point = job.point;
    const app::PickedPoint& p = job.point;
    result.readout = job.evaluator->evaluate(job.tool, p.speed_rpm, p.depth_mm, p.feed_mm_per_tooth);
    if (job.with_power_limit) result.power_limit_mm = job.evaluator->powerLimitMm(job.tool, p.feed_mm_per_tooth);
    reply([this, result = std::move(result)] {
      busy_ = false;
      emit evaluated(result);
      if (queued_) {
        auto [next, next_generation] = std::move(*queued_);
        queued_.reset();
        run(std::move(next), next_generation);
      }
    });
  });
}

}  // namespace mx::gui
