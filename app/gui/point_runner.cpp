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
  latest_->store(generation);
  if (!busy_) {
    run(std::move(job), generation);
    return generation;
  }
  if (queued_) job.with_power_limit = job.with_power_limit || queued_->first.with_power_limit;
  queued_.emplace(std::move(job), generation);
  return generation;
}

void PointRunner::run(PointJob job, quint64 generation) {
  busy_ = true;
  channel_.start(&pool_, [this, job = std::move(job), generation, latest = latest_](const EngineReply& reply) {
    PointJobResult result;
    result.generation = generation;
    result.evaluator = job.evaluator;
    result.tool = job.tool;
    result.point = job.point;
    const app::PickedPoint& p = job.point;
    result.readout = job.evaluator->evaluate(job.tool, p.speed_rpm, p.depth_mm, p.feed_mm_per_tooth);
    reply([this, result] { emit evaluated(result); });
    bool left = false;
    if (job.with_power_limit) {
      if (latest->load() == generation) {
        result.readout.reset();
        result.power_limit_mm = job.evaluator->powerLimitMm(job.tool, p.feed_mm_per_tooth);
        reply([this, result] { emit evaluated(result); });
      } else {
        left = true;  // a newer request waits: the curve is computed for it
      }
    }
    reply([this, left] { finished(left); });
  });
}

void PointRunner::finished(bool power_limit_left) {
  busy_ = false;
  if (!queued_) return;
  auto [next, next_generation] = std::move(*queued_);
  queued_.reset();
  next.with_power_limit = next.with_power_limit || power_limit_left;
  run(std::move(next), next_generation);
}

}  // namespace mx::gui
