#include "stability/semi_discretization.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include "model/vector_state.h"
#include "stability/sdm_arnoldi.h"
#include "stability/sdm_boundary.h"
#include "stability/sdm_model.h"

namespace mx {

namespace {

void requireSteps(int steps) {
  if (steps < 4) {
    throw InvalidInput("steps_per_period = " + std::to_string(steps) + " is outside the allowed range [4, inf)");
  }
}

constexpr int kMinAutoSteps = 60;
constexpr int kMaxAutoSteps = 1000;
constexpr double kAutoPhasePerStep = 0.3;  // rad of the fastest mode per step
constexpr double kAutoStepsInCut = 20.0;

// Models by step count, each with its own boundary search (the Arnoldi warm start has the model's size).
struct SdmSolvers {
  std::unique_ptr<SdmModel> model;
  std::unique_ptr<SdmBoundarySearch> search;
};

void requireSpeed(double speed) {
  if (!(speed > 0.0) || !std::isfinite(speed)) {
    std::ostringstream msg;
    msg << "spindle speed = " << speed << " rev/s is outside the allowed range (0, inf)";
    throw InvalidInput(msg.str());
  }
}

void requireDepth(double depth) {
  if (!(depth >= 0.0) || !std::isfinite(depth)) {
    std::ostringstream msg;
    msg << "axial depth = " << depth << " m is outside the allowed range [0, inf)";
    throw InvalidInput(msg.str());
  }
}

void validate(const MillingSetup& setup, const std::vector<double>& speeds, const SdmOptions& o) {
  setup.validateGeometry();
  if (o.steps_per_period != kAutoSdmSteps) requireSteps(o.steps_per_period);
  SdmModel::requireDelayOrder(o.delay_order, o.steps_per_period == kAutoSdmSteps ? kMinAutoSteps : o.steps_per_period);
  for (double n : speeds) requireSpeed(n);
  const double limit = smallestDecayRate(setup.modes_x, setup.modes_y);
  if (!(o.delta_per_s >= 0.0 && o.delta_per_s < limit)) {
    std::ostringstream msg;
    msg << "delta = " << o.delta_per_s << " 1/s is outside the allowed range [0, " << limit
        << ") (the smallest modal decay rate zeta*omega_n)";
    throw InvalidInput(msg.str());
  }
  if (!(o.max_depth_m > 0.0) || !std::isfinite(o.max_depth_m)) {
    std::ostringstream msg;
    msg << "max_depth_m = " << o.max_depth_m << " m is outside the allowed range (0, inf)";
    throw InvalidInput(msg.str());
  }
  if (!(o.depth_tolerance > 0.0 && o.depth_tolerance <= 0.1)) {
    std::ostringstream msg;
    msg << "depth_tolerance = " << o.depth_tolerance << " is outside the allowed range (0, 0.1]";
    throw InvalidInput(msg.str());
  }
}

}  // namespace

int autoSdmSteps(const MillingSetup& setup, double spindle_rev_per_s) {
  setup.validateGeometry();
  requireSpeed(spindle_rev_per_s);
  double omega_max = 0.0;
  for (const ModalAxis* axis : {&setup.modes_x, &setup.modes_y})
    for (const Mode& m : *axis) omega_max = std::max(omega_max, m.angularFrequency());
  const double period = 1.0 / (spindle_rev_per_s * setup.teeth);
  const double pitch = setup.toothPitchRad();
  const double cut = std::clamp(setup.immersion.exit_rad - setup.immersion.entry_rad, 1e-6, pitch);
  const double wanted =
      std::max({double(kMinAutoSteps), omega_max * period / kAutoPhasePerStep, kAutoStepsInCut * pitch / cut});
  const double rounded = 10.0 * std::ceil(std::min(wanted, double(kMaxAutoSteps)) / 10.0);
  return static_cast<int>(rounded);
}

SdmMultiplier sdmDominantMultiplier(const MillingSetup& setup, double spindle_rev_per_s, double depth_m,
                                    int steps_per_period, int delay_order) {
  clearUpperVectorState();
  setup.validateGeometry();
  requireSteps(steps_per_period);
  requireSpeed(spindle_rev_per_s);
  requireDepth(depth_m);
  const SdmModel model(setup, steps_per_period, delay_order);
  if (model.modalStates() == 0) return {};  // rigid tool: no dynamics, no regeneration
  SdmMonodromy map;
  model.build(spindle_rev_per_s, depth_m, model.freeStep(spindle_rev_per_s), map);
  const SdmEigenpair pair = SdmArnoldi().dominant(map);
  return {pair.value, map.chatterFrequencyHz(pair.value, pair.vector, model.principalPeriodS(spindle_rev_per_s))};
}

double sdmSpectralRadius(const MillingSetup& setup, double spindle_rev_per_s, double depth_m, int steps_per_period,
                         int delay_order) {
  return std::abs(sdmDominantMultiplier(setup, spindle_rev_per_s, depth_m, steps_per_period, delay_order).value);
}

// Continuation in speed: each speed's search (SdmBoundarySearch::solve) starts from the previous
// finite b_lim (cold estimate at the first speed or when none has been found yet), brackets outward
// geometrically (downward while unstable), solves log rho + delta T = 0 by Brent's method, then scans
// below for a lower crossing (islands) down to half the lowest b_lim so far. The Arnoldi start vector
// is the previous dominant eigenvector.
LobeDiagram computeSdmLobes(const MillingSetup& setup, const std::vector<double>& speeds_rev_per_s,
                            const SdmOptions& options, const JobControl& control) {
  clearUpperVectorState();
  validate(setup, speeds_rev_per_s, options);
  LobeDiagram out;
  out.delta_per_s = options.delta_per_s;
  out.speed_rev_per_s = speeds_rev_per_s;
  out.envelope_depth_m.assign(speeds_rev_per_s.size(), LobeDiagram::kNone);
  out.envelope_chatter_hz.assign(speeds_rev_per_s.size(), 0.0);

  const double cold = SdmBoundarySearch::coldGuess(setup, options.max_depth_m);
  std::map<int, SdmSolvers> solvers;
  auto solverFor = [&](double speed) -> SdmSolvers& {
    const int m = options.steps_per_period == kAutoSdmSteps ? autoSdmSteps(setup, speed) : options.steps_per_period;
    SdmSolvers& s = solvers[m];
    if (!s.model) {
      s.model = std::make_unique<SdmModel>(setup, m, options.delay_order, options.helix_slices);
      s.search = std::make_unique<SdmBoundarySearch>(*s.model, options);
      s.search->setColdGuess(cold);
    }
    return s;
  };
  const bool rigid = setup.modes_x.empty() && setup.modes_y.empty();
  double guess = 0.0;
  double lowest = LobeDiagram::kNone;
  const size_t count = speeds_rev_per_s.size();
  for (size_t i = 0; i < count; ++i) {
    if (control.cancelled()) throw Cancelled();
    if (!rigid) {
      const SdmBoundaryPoint p = solverFor(speeds_rev_per_s[i]).search->solve(speeds_rev_per_s[i], guess, lowest);
      out.envelope_depth_m[i] = p.depth_m;
      if (std::isfinite(p.depth_m)) {
        out.envelope_chatter_hz[i] = p.chatter_hz;
        guess = p.depth_m;
        lowest = std::min(lowest, p.depth_m);
      }
    }
    control.report(static_cast<double>(i + 1) / static_cast<double>(count));
  }
  out.minima = envelopeMinima(out.speed_rev_per_s, out.envelope_depth_m, out.envelope_chatter_hz);
  return out;
}

}  // namespace mx
