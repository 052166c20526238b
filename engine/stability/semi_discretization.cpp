#include "stability/semi_discretization.h"

#include <algorithm>
#include <cmath>
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

void requireTeeth(const MillingSetup& setup) {
  if (setup.teeth < 1) throw InvalidInput("teeth = " + std::to_string(setup.teeth) + " is outside [1, inf)");
}

void validate(const MillingSetup& setup, const std::vector<double>& speeds, const SdmOptions& o) {
  requireTeeth(setup);
  requireSteps(o.steps_per_period);
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

SdmMultiplier sdmDominantMultiplier(const MillingSetup& setup, double spindle_rev_per_s, double depth_m,
                                    int steps_per_period) {
  clearUpperVectorState();
  requireTeeth(setup);
  requireSteps(steps_per_period);
  requireSpeed(spindle_rev_per_s);
  requireDepth(depth_m);
  const SdmModel model(setup, steps_per_period);
  if (model.modalStates() == 0) return {};  // rigid tool: no dynamics, no regeneration
  SdmMonodromy map;
  model.build(spindle_rev_per_s, depth_m, model.freeStep(spindle_rev_per_s), map);
  const SdmEigenpair pair = SdmArnoldi().dominant(map);
  return {pair.value, map.chatterFrequencyHz(pair.value, pair.vector, model.toothPeriodS(spindle_rev_per_s))};
}

double sdmSpectralRadius(const MillingSetup& setup, double spindle_rev_per_s, double depth_m, int steps_per_period) {
  return std::abs(sdmDominantMultiplier(setup, spindle_rev_per_s, depth_m, steps_per_period).value);
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

  const SdmModel model(setup, options.steps_per_period);
  SdmBoundarySearch search(model, options);
  search.setColdGuess(SdmBoundarySearch::coldGuess(setup, options.max_depth_m));
  double guess = 0.0;
  double lowest = LobeDiagram::kNone;
  const size_t count = speeds_rev_per_s.size();
  for (size_t i = 0; i < count; ++i) {
    if (control.cancelled()) throw Cancelled();
    if (model.modalStates() > 0) {
      const SdmBoundaryPoint p = search.solve(speeds_rev_per_s[i], guess, lowest);
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
