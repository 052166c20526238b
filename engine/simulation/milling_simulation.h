#pragma once
// Time-domain milling simulation with chatter detection (Rubio et al. 2006, section 2; eq. 1-7, 11, 12).
// The tool starts at rest in a surface cut by a rigid tool (zero pre-history) and runs `revolutions`
// spindle revolutions; the indicators use the last `evaluated_revolutions`.
#include "core/cancellation.h"
#include "core/invalid_input.h"
#include "model/milling_setup.h"
#include "simulation/simulation_types.h"

namespace mx {

// Throws InvalidInput naming the quantity, its value and the allowed range: speed > 0, depth >= 0,
// feed > 0, revolutions > evaluated_revolutions >= 1, |a| < 1, f_ss >= 0, steps_per_tooth_period = 0 or
// >= 4 (and >= minimumStepsPerToothPeriod), axial_slices in [0, 720], record_every >= 1, teeth >= 1,
// the cutter geometry (MillingSetup::validateGeometry), D > 0, K_t >= 0, modes with f > 0, k > 0,
// 0 <= zeta < 1, at most kMaxSimulationSteps steps.
void validateSimulationInputs(const MillingSetup& setup, const OperatingPoint& point, const SimulationOptions& options);

// The work of one run: integration steps (m n_t revolutions, m the steps per tooth period, automatic
// or given) and recorded trace samples (at most the steps). The limit keeps a run within about 15 s on
// a 2-core machine (1.7e6 steps/s for a 3-tooth cutter) and its evaluation window and trace under
// about 1 GB.
struct SimulationSize {
  int steps_per_tooth_period = 0;
  double steps = 0.0;
  double trace_samples = 0.0;
};
inline constexpr double kMaxSimulationSteps = 2e7;
// For a valid speed, teeth and revolutions; does not check the limits.
SimulationSize simulationSize(const MillingSetup& setup, const OperatingPoint& point, const SimulationOptions& options);

// Polls control.cancelled() once per revolution (throws Cancelled) and reports the fraction done.
SimulationResult simulateMilling(const MillingSetup& setup, const OperatingPoint& point,
                                 const SimulationOptions& options, const JobControl& control = {});

}  // namespace mx
