#pragma once
// Fixed-step RK4 integration of the regenerative milling model (2006, section 2E; eq. 1-7):
//   modal equations (ModalDynamics) driven by F = sum_j toothForce(phi_j, h_j),
//   h_j = s_t sin phi_j + (x(t) - x(t - tau)) sin phi_j + (y(t) - y(t - tau)) cos phi_j,  F_j = 0 for h_j <= 0
// with dt = T/m so that at constant speed x(t - T) is a stored sample; the half-step delayed values are
// cubic Hermite interpolants (DelayHistory). Steps in which a tooth enters or leaves the immersion are
// split there (EngagementPlanner), keeping RK4's order with the force discontinuity of partial
// immersion. Under spindle speed variation tau(t) comes from SpindleKinematics and the history is
// Hermite-interpolated at t - tau(t).
// Real cutters (cutter_edges.h): tooth j has its own delays tau_jk = A_jk / Omega (variable pitch:
// fractional in dt, Hermite-interpolated), its runout term rho_j - rho_{j+k}, and a helical tooth is
// the sum of its axial slices, each an edge with its own entry and exit events.
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include "core/cancellation.h"
#include "model/milling_setup.h"
#include "simulation/chatter_detection.h"
#include "simulation/cutter_edges.h"
#include "simulation/modal_dynamics.h"
#include "simulation/regenerative_force.h"
#include "simulation/simulation_types.h"

namespace mx {

class TimeDomainSimulator {
 public:
  enum class Kernel {
    Automatic,      // tabulated angles and fixed delay at constant speed, the general kernel otherwise
    ConstantSpeed,  // requires a constant speed
    VariableSpeed,  // general kernel: angles from theta(t), delay tau(t) by Newton (also valid for a = 0)
  };

  // The inputs must already be valid (simulateMilling validates them).
  TimeDomainSimulator(const MillingSetup& setup, const OperatingPoint& point, const SimulationOptions& options);

  int stepsPerToothPeriod() const { return steps_per_tooth_; }
  int axialSlices() const { return axial_slices_; }
  double dt() const { return dt_; }
  std::int64_t totalSteps() const { return total_steps_; }

  void run(const JobControl& control = {}, Kernel kernel = Kernel::Automatic);

  const SimulationTrace& trace() const { return trace_; }
  SimulationTrace takeTrace() { return std::move(trace_); }
  const WindowSignals& window() const { return window_; }
  const std::vector<double>& finalState() const { return state_; }
  // The run stops at the first revolution boundary where |x| or |y| exceeds the divergence limit.
  bool diverged() const { return diverged_; }
  int simulatedRevolutions() const { return simulated_revolutions_; }

 private:
  template <class Plans, class Delays>
  void integrate(Plans& plans, Delays& delays, const JobControl& control);
  // Steps from the initial state until total_steps_ or the divergence stop; returns the steps taken.
  template <class Plans, class Stepper, class Recorders>
  std::int64_t stepAll(const ModalDynamics& dynamics, Plans& plans, Stepper& stepper, Recorders& recorders,
                       const JobControl& control);
  double divergenceLimit() const;

  MillingSetup setup_;
  OperatingPoint point_;
  SimulationOptions options_;
  int steps_per_tooth_ = 0;
  int axial_slices_ = 1;
  std::vector<CutterEdge> edges_;
  double dt_ = 0.0;
  std::int64_t total_steps_ = 0;
  std::int64_t steps_per_rev_ = 0;
  bool diverged_ = false;
  int simulated_revolutions_ = 0;
  std::vector<double> state_;
  SimulationTrace trace_;
  WindowSignals window_;
};

// m = max(32, ceil(40 f_max T), minimumStepsPerToothPeriod): at least 40 steps per period of the highest
// mode and 32 per (mean) tooth period T = 1 / (n_t N).
int automaticStepsPerToothPeriod(const MillingSetup& setup, double spindle_rev_per_s);

// The shortest delay (the smallest pitch) must span kMinDelaySteps steps even at the fastest speed of a
// spindle speed variation (|a| < 1), so that every delayed instant is an already computed sample:
// m >= ceil(4 (2 pi / n_t) / min_j pitch_j) (4 for uniform pitch).
inline constexpr double kMinDelaySteps = 4.0;
int minimumStepsPerToothPeriod(const MillingSetup& setup);

// Axial slices of a helical cutter in the simulation. Each slice is an edge whose entry and exit split the
// RK4 steps and whose chip is summed at every stage, so the cost grows somewhat faster than the slice
// count (4-flute, 16.5 deg of lag, 20 revolutions: 1.3 ms with 4 slices, 7 ms with 32, 46 ms with 128).
// The model's default (defaultAxialSlices: 1 deg of lag per slice, up to 720) would make long helical
// edges cost seconds per run. The simulation allows kSimulationSliceLagRad of lag per slice, capped at
// kMaxSimulationSlices: the peak vibration then converges at second order and is within 0.1 % of the
// converged value, the sampled peak force within 0.5 % (its own step error; both measured in
// tests/simulation/test_cutter_geometry_simulation.cpp). `requested` >= 1 overrides; no helix: 1.
inline constexpr double kSimulationSliceLagRad = 2.0 * std::numbers::pi / 180.0;
inline constexpr int kMaxSimulationSlices = 90;
int simulationAxialSlices(const MillingSetup& setup, double depth_m, int requested);

}  // namespace mx
