#include "simulation/milling_simulation.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "model/axial_slices.h"
#include "model/vector_state.h"
#include "simulation/chatter_detection.h"
#include "simulation/cutter_edges.h"
#include "simulation/time_domain_simulator.h"

namespace mx {

namespace {

template <class T>
void require(bool ok, const std::string& quantity, T value, const char* range) {
  if (ok) return;
  std::ostringstream message;
  message << "simulateMilling: " << quantity << " = " << value << " is outside the allowed range " << range;
  throw InvalidInput(message.str());
}

void validateAxis(const ModalAxis& axis, const char* name) {
  for (std::size_t r = 0; r < axis.size(); ++r) {
    const Mode& mode = axis[r];
    const std::string prefix = std::string(name) + "[" + std::to_string(r) + "] ";
    require(std::isfinite(mode.natural_frequency_hz) && mode.natural_frequency_hz > 0.0,
            prefix + "natural frequency [Hz]", mode.natural_frequency_hz, "(0, inf)");
    require(std::isfinite(mode.stiffness_n_per_m) && mode.stiffness_n_per_m > 0.0, prefix + "stiffness [N/m]",
            mode.stiffness_n_per_m, "(0, inf)");
    require(mode.damping_ratio >= 0.0 && mode.damping_ratio < 1.0, prefix + "damping ratio", mode.damping_ratio,
            "[0, 1)");
  }
}

}  // namespace

void validateSimulationInputs(const MillingSetup& setup, const OperatingPoint& point,
                              const SimulationOptions& options) {
  const double n = point.spindle_rev_per_s;
  require(std::isfinite(n) && n > 0.0, "spindle speed [rev/s]", n, "(0, inf)");
  require(std::isfinite(point.axial_depth_m) && point.axial_depth_m >= 0.0, "axial depth [m]", point.axial_depth_m,
          "[0, inf)");
  require(std::isfinite(point.feed_per_tooth_m) && point.feed_per_tooth_m > 0.0, "feed per tooth [m]",
          point.feed_per_tooth_m, "(0, inf)");
  require(options.evaluated_revolutions >= 1, "evaluated revolutions", options.evaluated_revolutions,
          "[1, revolutions)");
  require(options.revolutions > options.evaluated_revolutions, "revolutions", options.revolutions,
          "(evaluated revolutions, inf)");
  const double a = options.ssv.amplitude_ratio;
  require(std::isfinite(a) && std::abs(a) < 1.0, "speed variation amplitude ratio", a, "(-1, 1)");
  require(std::isfinite(options.ssv.frequency_hz) && options.ssv.frequency_hz >= 0.0, "speed variation frequency [Hz]",
          options.ssv.frequency_hz, "[0, inf)");
  require(options.steps_per_tooth_period == 0 || options.steps_per_tooth_period >= 4, "steps per tooth period",
          options.steps_per_tooth_period, "0 (automatic) or [4, inf)");
  require(options.regenerative_passes >= 1 && options.regenerative_passes <= kMaxRegenerativePasses,
          "regenerative passes", options.regenerative_passes, "[1, 8]");
  require(std::isfinite(options.divergence_limit_m) && options.divergence_limit_m >= 0.0, "divergence limit [m]",
          options.divergence_limit_m, "0 (automatic) or (0, inf)");
  require(options.record_every >= 1, "record_every", options.record_every, "[1, inf)");
  require(std::isfinite(options.initial_x_m) && (options.initial_x_m == 0.0 || !setup.modes_x.empty()),
          "initial x displacement [m] (x axis rigid if no modes)", options.initial_x_m, "finite; 0 on a rigid axis");
  require(std::isfinite(options.initial_y_m) && (options.initial_y_m == 0.0 || !setup.modes_y.empty()),
          "initial y displacement [m] (y axis rigid if no modes)", options.initial_y_m, "finite; 0 on a rigid axis");
  require(setup.teeth >= 1, "teeth", setup.teeth, "[1, inf)");
  require(std::isfinite(setup.diameter_m) && setup.diameter_m > 0.0, "diameter [m]", setup.diameter_m, "(0, inf)");
  setup.validateGeometry();
  require(options.axial_slices >= 0 && options.axial_slices <= kMaxAxialSlices, "axial slices", options.axial_slices,
          "0 (automatic) or [1, 720]");
  if (options.steps_per_tooth_period > 0) {
    const int least = minimumStepsPerToothPeriod(setup);  // the smallest pitch spans >= 4 steps
    require(options.steps_per_tooth_period >= least, "steps per tooth period (smallest pitch)",
            options.steps_per_tooth_period, ("0 (automatic) or [" + std::to_string(least) + ", inf)").c_str());
  }
  require(std::isfinite(setup.tangential_coefficient_pa) && setup.tangential_coefficient_pa >= 0.0,
          "tangential coefficient K_t [Pa]", setup.tangential_coefficient_pa, "[0, inf)");
  require(std::isfinite(setup.radial_ratio), "radial ratio K_r", setup.radial_ratio, "finite");
  validateAxis(setup.modes_x, "modes_x");
  validateAxis(setup.modes_y, "modes_y");

  const SimulationSize size = simulationSize(setup, point, options);
  require(size.steps <= kMaxSimulationSteps, "total integration steps (m n_t revolutions)", size.steps, "[1, 2e7]");
}

SimulationSize simulationSize(const MillingSetup& setup, const OperatingPoint& point,
                              const SimulationOptions& options) {
  SimulationSize size;
  size.steps_per_tooth_period = options.steps_per_tooth_period > 0
                                    ? options.steps_per_tooth_period
                                    : automaticStepsPerToothPeriod(setup, point.spindle_rev_per_s);
  size.steps = static_cast<double>(size.steps_per_tooth_period) * setup.teeth * options.revolutions;
  size.trace_samples = std::ceil(size.steps / std::max(1, options.record_every));
  return size;
}

SimulationResult simulateMilling(const MillingSetup& setup, const OperatingPoint& point,
                                 const SimulationOptions& options, const JobControl& control) {
  clearUpperVectorState();
  validateSimulationInputs(setup, point, options);
  TimeDomainSimulator simulator(setup, point, options);
  simulator.run(control);

  ChatterCriteria criteria;
  criteria.eta_threshold = options.eta_threshold;
  criteria.chip_ratio_threshold = options.chip_ratio_threshold;
  criteria.teeth = setup.teeth;
  criteria.nominal_rev_per_s = point.spindle_rev_per_s;
  criteria.ssv = options.ssv;
  criteria.forced_at_spindle_harmonics = !teethSharePasses(setup);

  SimulationResult result;
  result.indicators = detectChatter(simulator.window(), criteria);
  result.steps_per_tooth_period = simulator.stepsPerToothPeriod();
  result.dt_s = simulator.dt();
  result.simulated_revolutions = simulator.simulatedRevolutions();
  result.diverged = simulator.diverged();
  result.trace = simulator.takeTrace();
  return result;
}

}  // namespace mx
