#pragma once
// Reference solution of the same regenerative milling model (2006, eq. 1-7) with SUNDIALS CVODE
// (variable-order Adams, tolerance-controlled), independent of the RK4 kernel: the delayed state
// r(t - tau) comes from CVODE's own output history on the grid t_k = k T/m, Hermite-interpolated with the
// stored velocities; the forces come from mx::toothForce. For cross-checking the RK4 simulation.
#include "model/milling_setup.h"
#include "simulation/simulation_types.h"

namespace mx {

// Constant speed, tool at rest in a rigid-tool surface at t = 0. The trace is sampled at t_k = k T/m,
// k = 0 .. revolutions n_t m - 1 (m = samples_per_tooth_period, 0 = automaticStepsPerToothPeriod), i.e.
// at the same instants as simulateMilling with the same m. Throws InvalidInput, or CvodeError when a
// SUNDIALS call fails. regenerative_passes and axial_slices as in SimulationOptions (1 = eq. 7; the
// cutter geometry of cutter_edges.h: per-tooth delays, runout, helix slices).
SimulationTrace simulateMillingCvode(const MillingSetup& setup, const OperatingPoint& point, int revolutions,
                                     double rtol, int samples_per_tooth_period = 0, int regenerative_passes = 1,
                                     int axial_slices = 0);

}  // namespace mx
