#pragma once
// Inputs and outputs of the time-domain milling simulation (Rubio et al. 2006, section 2A-2F).
// SI units throughout: s, m, N, W, Hz, rev/s.
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace mx {

// Sinusoidal spindle speed variation (2006, eq. 12): N(t) = N0 (1 + a sin(2 pi f t)).
struct SpindleSpeedVariation {
  double amplitude_ratio = 0.0;  // a, |a| < 1
  double frequency_hz = 0.0;     // f >= 0
};

// The samples recorded during one revolution, for live views. The spans point into the result's
// trace and are valid only during the callback.
struct SimulationChunk {
  int revolution = 0;           // revolutions completed (1-based)
  int revolutions = 0;          // total revolutions simulated
  std::size_t first_index = 0;  // index of time_s[0] in the full trace
  std::span<const double> time_s, x_m, y_m, fx_n, fy_n, force_n, power_w;
};

struct SimulationOptions {
  int revolutions = 60;            // simulated spindle revolutions (from rest, rigid pre-history)
  int evaluated_revolutions = 20;  // the indicators use the last ones
  int steps_per_tooth_period =
      0;                 // m, dt = T/m (T the mean tooth period); 0 = automatic (automaticStepsPerToothPeriod)
  int axial_slices = 0;  // slices of a helical cutter; 0 = automatic (simulationAxialSlices)
  SpindleSpeedVariation ssv;
  int record_every = 1;                                  // keep every k-th integration step in the trace
  std::function<void(const SimulationChunk&)> on_chunk;  // optional, called once per revolution

  // Tool released at t = 0 from this displacement with zero velocity (free-vibration checks).
  // Split over an axis' modes like a static deflection (q_r proportional to 1/k_r).
  double initial_x_m = 0.0;
  double initial_y_m = 0.0;

  // Surface memory: h_j = min_{k=1..K} [k s_t sin phi + (x(t) - x(t - kT)) sin phi + (y(t) - y(t - kT)) cos phi]
  // (with variable pitch and runout the delays, feeds and runout terms of cutter_edges.h).
  // K = 1 is eq. 7 as printed; K > 1 also remembers passes where the tooth left the cut (h <= 0), which
  // usually makes chatter saturate at a finite amplitude (not guaranteed for finite K). Identical to
  // K = 1 while every tooth stays in the cut. With runout larger than the feed a tooth can leave no
  // chip at all: K >= n_t then gives the surface the next cutting tooth really left.
  int regenerative_passes = 1;

  // Eq. 7 is positively homogeneous in (s_t, x, y), so beyond the stability limit the vibration can grow
  // without bound: the run stops at the first step where |x| or |y| exceeds this limit (0 = automatic:
  // D/2) and is evaluated over the last revolutions it reached (SimulationResult::diverged).
  double divergence_limit_m = 0.0;

  double eta_threshold = 1.3;          // 2006, eq. 11
  double chip_ratio_threshold = 1.25;  // Pareto paper, Rule 15
};

// Sampled at t_n = n dt (state at t_n and the force it produces, as the right-hand limit: a tooth
// entering exactly at t_n cuts), decimated by record_every. P = pi D N(t) sum_j F_tj (Pareto eq. 8).
struct SimulationTrace {
  std::vector<double> time_s, x_m, y_m, fx_n, fy_n, force_n, power_w;
  std::size_t size() const { return time_s.size(); }
};

struct ChatterIndicators {
  // max|F_dyn| / max|F_static| over the evaluated window (eq. 11); 1 when b = 0. For unequal teeth
  // (variable pitch, runout) at constant speed the reference is the revolution-synchronous average of
  // |F_dyn| (WindowRecorder), as is the chip ratio's.
  double eta = 0.0;
  double chip_ratio = 0.0;                     // max h_dyn / max h_static (Rule 15)
  bool chatter_by_eta = false;                 // eta >= eta_threshold
  bool chatter_by_chip_ratio = false;          // chip_ratio >= chip_ratio_threshold
  bool chatter = false;                        // either criterion
  std::optional<double> chatter_frequency_hz;  // present only when chatter is detected
  double tooth_passing_hz = 0.0;               // n_t N0
  double peak_force_n = 0.0;                   // max resultant |F| over the window
  double peak_power_w = 0.0;                   // max v sum_j F_tj over the window (Pareto eq. 8)
  double a_chatter = 0.0;                      // amplitude of the largest non-harmonic peak (reported even when stable)
  double a_toothpass = 0.0;                    // amplitude at the tooth-passing frequency
  double largest_nonharmonic_hz = 0.0;         // frequency of that peak (0 if none)
};

struct SimulationResult {
  SimulationTrace trace;
  ChatterIndicators indicators;
  int steps_per_tooth_period = 0;
  double dt_s = 0.0;
  int simulated_revolutions = 0;  // < options.revolutions when the run diverged
  bool diverged = false;          // displacement beyond options.divergence_limit_m
};

}  // namespace mx
