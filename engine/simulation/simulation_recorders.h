#pragma once
// What the time-domain simulation keeps of each integration step: the decimated trace (with its
// per-revolution chunks for live views), and the evaluated window that the chatter indicators read.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "simulation/chatter_detection.h"
#include "simulation/simulation_types.h"

namespace mx {

// The state at t_n = n dt and the force it produces (right-hand limit: a tooth entering at t_n cuts),
// with the rigid tool's force and chip over the same teeth as the static reference (eq. 11, Rule 15).
struct StepSample {
  std::int64_t n = 0;
  double t_s = 0.0;
  double x_m = 0.0, y_m = 0.0;
  double fx_n = 0.0, fy_n = 0.0;
  double force_n = 0.0;  // |F|
  double power_w = 0.0;  // pi D N(t) sum_j F_tj (Pareto eq. 8)
  double chip_m = 0.0;   // largest chip thickness of the engaged teeth
  double static_force_n = 0.0;
  double static_chip_m = 0.0;
};

// Every record_every-th step into the trace; the samples of each finished revolution go to on_chunk.
class TraceRecorder {
 public:
  // Clears `trace` and reserves room for the samples of total_steps steps.
  TraceRecorder(SimulationTrace& trace, const SimulationOptions& options, std::int64_t total_steps);

  void record(const StepSample& s);
  // Hands the samples recorded since the previous call to on_chunk (if any); `revolution` is 1-based.
  void finishRevolution(int revolution);

 private:
  SimulationTrace& trace_;
  const std::function<void(const SimulationChunk&)>& on_chunk_;  // the options' callback, not a copy
  int revolutions_;
  std::int64_t record_every_;
  std::int64_t until_record_ = 0;
  std::size_t chunk_begin_ = 0;
};

// Indicator inputs per revolution, and the signals of the last E revolutions in rings, so that a run
// stopped by divergence is evaluated over the last E revolutions it simulated.
//
// `synchronous_reference` (a cutter with unequal teeth at constant speed): the forced vibration of a
// stable cut repeats only once a revolution and its delays are not that period, so it changes the chip
// and the rigid tool's force is no longer what a stable cut produces. The reference of eta and of the
// chip ratio is then the revolution-synchronous average of the simulated |F| and chip over the complete
// evaluated revolutions (their forced part; non-synchronous chatter averages out), when there are two
// or more. For uniform teeth at a stable point that average is the rigid tool's force (eq. 7), so the
// reference stays the rigid tool's there.
class WindowRecorder {
 public:
  WindowRecorder(int revolutions, int evaluated_revolutions, std::int64_t steps_per_revolution, double dt,
                 bool synchronous_reference = false);

  void record(const StepSample& s);
  // The last E of the `touched` revolutions (those with a sample) after `steps` steps.
  WindowSignals window(std::int64_t steps, int touched) const;

 private:
  struct RevolutionStats {
    double max_force = 0.0, max_static_force = 0.0, max_chip = 0.0, max_static_chip = 0.0, peak_power = 0.0;
  };

  int evaluated_revolutions_;
  std::int64_t steps_per_rev_;
  double dt_;
  std::vector<RevolutionStats> stats_;
  std::int64_t ring_size_;
  std::vector<double> ring_force_, ring_x_, ring_y_;
  bool synchronous_reference_;
  std::vector<double> ring_chip_;  // only with the synchronous reference
};

}  // namespace mx
