#include "stability/lobe_computation.h"

#include "core/invalid_input.h"
#include "stability/semi_discretization.h"
#include "stability/zero_order_lobes.h"

namespace mx {

LobeDiagram computeLobes(const MillingSetup& setup, const std::vector<double>& speeds_rev_per_s,
                         const LobeSettings& settings, const JobControl& control) {
  if (settings.method == StabilityMethod::ZeroOrder) {
    ZoaOptions o;
    o.delta_per_s = settings.delta_per_s;
    o.max_depth_m = settings.max_depth_m;
    o.dynamics = settings.dynamics;
    return computeZoaLobes(setup, speeds_rev_per_s, o, control);
  }
  if (settings.dynamics == DynamicsSource::Measured)
    throw InvalidInput("semi-discretization needs a state-space model: use fitted modes");
  SdmOptions o;
  o.delta_per_s = settings.delta_per_s;
  o.max_depth_m = settings.max_depth_m;
  o.steps_per_period = settings.sdm_steps_per_period;
  o.delay_order = settings.sdm_delay_order;
  o.helix_slices = settings.sdm_helix_slices;
  return computeSdmLobes(setup, speeds_rev_per_s, o, control);
}

}  // namespace mx
