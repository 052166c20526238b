#include "control/model_based_force_loop.h"

#include <algorithm>
#include <cmath>

#include "core/invalid_input.h"

namespace mx {
namespace {

const ModelBasedForceLoopSettings& checked(const ModelBasedForceLoopSettings& s) {
  auto positive = [](const char* field, double v) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw InvalidInput(std::string("model-based force loop: ") + field + " = " + std::to_string(v) +
                         " s: must be > 0 and finite");
  };
  positive("period", s.period_s);
  positive("time_constant", s.time_constant_s);
  if (!(s.min_feed_fraction > 0.0 && s.min_feed_fraction <= 1.0))
    throw InvalidInput("model-based force loop: min_feed_fraction = " + std::to_string(s.min_feed_fraction) +
                       ": must be in (0, 1]");
  return s;
}

}  // namespace

ModelBasedForceLoop::ModelBasedForceLoop(ModelBasedForceLoopSettings settings)
    : settings_(checked(settings)),
      model_(settings.controller),
      pole_(std::exp(-settings.period_s / settings.time_constant_s)) {}

double ModelBasedForceLoop::maxFeedRate(double N) const {
  const ModelBasedForceSettings& c = settings_.controller;
  return std::min(c.max_feed_rate_m_per_s, c.max_feed_per_tooth_m * c.teeth * N);
}

double ModelBasedForceLoop::clampFeed(double v, double N) const {
  const double top = maxFeedRate(N);
  return std::clamp(v, settings_.min_feed_fraction * top, top);
}

void ModelBasedForceLoop::reset(double current_feed_m_per_s, double depth_m, double N) {
  if (!(N > 0.0) || !std::isfinite(N))
    throw InvalidInput("model-based force loop: spindle_speed = " + std::to_string(N) + " rev/s: must be > 0");
  const double start =
      settings_.reset_feed == ResetFeed::Model ? model_.feed(depth_m, N).feed_rate_m_per_s : current_feed_m_per_s;
  feed_rate_m_per_s_ = clampFeed(std::isfinite(start) ? start : 0.0, N);
}

double ModelBasedForceLoop::update(double F, double N) {
  if (!(F > 0.0) || !std::isfinite(F)) return feed_rate_m_per_s_;
  const double gain = (1.0 - pole_) / settings_.controller.model.feed_exponent;
  const double step = gain * std::log(settings_.controller.reference_force_N / F);
  feed_rate_m_per_s_ = clampFeed(feed_rate_m_per_s_ * std::exp(step), N);
  return feed_rate_m_per_s_;
}

std::string resetFeedName(ResetFeed r) {
  return r == ResetFeed::Model ? "model" : "current";
}

ResetFeed parseResetFeed(const std::string& name) {
  if (name == "current") return ResetFeed::Current;
  if (name == "model") return ResetFeed::Model;
  throw InvalidInput("model-based force loop: reset_feed = \"" + name + "\": must be \"current\" or \"model\"");
}

}  // namespace mx
