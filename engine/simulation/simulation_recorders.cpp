#include "simulation/simulation_recorders.h"

#include <algorithm>
#include <span>

namespace mx {

TraceRecorder::TraceRecorder(SimulationTrace& trace, const SimulationOptions& options, std::int64_t total_steps)
    : trace_(trace),
      on_chunk_(options.on_chunk),
      revolutions_(options.revolutions),
      record_every_(static_cast<std::int64_t>(options.record_every)) {
  const auto recorded = static_cast<std::size_t>((total_steps + record_every_ - 1) / record_every_);
  trace_ = SimulationTrace{};
  for (auto* v :
       {&trace_.time_s, &trace_.x_m, &trace_.y_m, &trace_.fx_n, &trace_.fy_n, &trace_.force_n, &trace_.power_w})
    v->reserve(recorded);
}

void TraceRecorder::record(const StepSample& s) {
  if (until_record_ == 0) {
    trace_.time_s.push_back(s.t_s);
    trace_.x_m.push_back(s.x_m);
    trace_.y_m.push_back(s.y_m);
    trace_.fx_n.push_back(s.fx_n);
    trace_.fy_n.push_back(s.fy_n);
    trace_.force_n.push_back(s.force_n);
    trace_.power_w.push_back(s.power_w);
    until_record_ = record_every_;
  }
  --until_record_;
}

void TraceRecorder::finishRevolution(int revolution) {
  if (on_chunk_ && trace_.size() > chunk_begin_) {
    const std::size_t count = trace_.size() - chunk_begin_;
    auto view = [&](const std::vector<double>& v) { return std::span<const double>(v.data() + chunk_begin_, count); };
    on_chunk_(SimulationChunk{revolution, revolutions_, chunk_begin_, view(trace_.time_s), view(trace_.x_m),
                              view(trace_.y_m), view(trace_.fx_n), view(trace_.fy_n), view(trace_.force_n),
                              view(trace_.power_w)});
  }
  chunk_begin_ = trace_.size();
}

WindowRecorder::WindowRecorder(int revolutions, int evaluated_revolutions, std::int64_t steps_per_revolution, double dt,
                               bool synchronous_reference)
    : evaluated_revolutions_(evaluated_revolutions),
      steps_per_rev_(steps_per_revolution),
      dt_(dt),
      stats_(static_cast<std::size_t>(revolutions)),
      ring_size_(steps_per_revolution * evaluated_revolutions),
      ring_force_(static_cast<std::size_t>(ring_size_)),
      ring_x_(ring_force_.size()),
      ring_y_(ring_force_.size()),
      synchronous_reference_(synchronous_reference),
      ring_chip_(synchronous_reference ? ring_force_.size() : 0) {}

void WindowRecorder::record(const StepSample& s) {
  RevolutionStats& r = stats_[static_cast<std::size_t>(s.n / steps_per_rev_)];
  r.max_force = std::max(r.max_force, s.force_n);
  r.max_static_force = std::max(r.max_static_force, s.static_force_n);
  r.max_chip = std::max(r.max_chip, s.chip_m);
  r.max_static_chip = std::max(r.max_static_chip, s.static_chip_m);
  r.peak_power = std::max(r.peak_power, s.power_w);
  const auto slot = static_cast<std::size_t>(s.n % ring_size_);
  ring_force_[slot] = s.force_n;
  ring_x_[slot] = s.x_m;
  ring_y_[slot] = s.y_m;
  if (synchronous_reference_) ring_chip_[slot] = s.chip_m;
}

namespace {
// The largest value of the average over `revolutions` consecutive revolutions at each step of the
// revolution, for the samples from step `first` on (ring slots modulo the ring size).
double largestSynchronousAverage(const std::vector<double>& ring, std::int64_t first, std::int64_t steps_per_rev,
                                 std::int64_t revolutions) {
  const auto ring_size = static_cast<std::int64_t>(ring.size());
  double largest = 0.0;
  for (std::int64_t p = 0; p < steps_per_rev; ++p) {
    double sum = 0.0;
    for (std::int64_t r = 0; r < revolutions; ++r)
      sum += ring[static_cast<std::size_t>((first + r * steps_per_rev + p) % ring_size)];
    largest = std::max(largest, sum / static_cast<double>(revolutions));
  }
  return largest;
}
}  // namespace

WindowSignals WindowRecorder::window(std::int64_t steps, int touched) const {
  const int first_revolution = std::max(0, touched - evaluated_revolutions_);
  WindowSignals w;
  w.sample_rate_hz = 1.0 / dt_;
  for (int r = first_revolution; r < touched; ++r) {
    const RevolutionStats& st = stats_[static_cast<std::size_t>(r)];
    w.max_force_n = std::max(w.max_force_n, st.max_force);
    w.max_static_force_n = std::max(w.max_static_force_n, st.max_static_force);
    w.max_chip_m = std::max(w.max_chip_m, st.max_chip);
    w.max_static_chip_m = std::max(w.max_static_chip_m, st.max_static_chip);
    w.peak_power_w = std::max(w.peak_power_w, st.peak_power);
  }
  for (auto* v : {&w.force_n, &w.x_m, &w.y_m})
    v->reserve(static_cast<std::size_t>(steps - first_revolution * steps_per_rev_));
  for (std::int64_t i = first_revolution * steps_per_rev_; i < steps; ++i) {
    const auto slot = static_cast<std::size_t>(i % ring_size_);
    w.force_n.push_back(ring_force_[slot]);
    w.x_m.push_back(ring_x_[slot]);
    w.y_m.push_back(ring_y_[slot]);
  }
  const std::int64_t first = first_revolution * steps_per_rev_;
  const std::int64_t complete = (steps - first) / steps_per_rev_;
  if (synchronous_reference_ && complete >= 2) {
    w.max_static_force_n = largestSynchronousAverage(ring_force_, first, steps_per_rev_, complete);
    w.max_static_chip_m = largestSynchronousAverage(ring_chip_, first, steps_per_rev_, complete);
  }
  return w;
}

}  // namespace mx
