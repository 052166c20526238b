#pragma once
// One entry point for the stability lobes of either method (Rule 1): the zeroth-order approximation
// (Rubio et al. 2006, eq. 8-10) or semi-discretization, with the delta margin.
#include <vector>

#include "core/cancellation.h"
#include "model/milling_setup.h"
#include "stability/lobe_diagram.h"
#include "stability/semi_discretization.h"

namespace mx {

enum class StabilityMethod { ZeroOrder, SemiDiscretization };

struct LobeSettings {
  StabilityMethod method = StabilityMethod::ZeroOrder;
  double delta_per_s = 0.0;                  // Rule 1.1
  double max_depth_m = 0.02;                 // envelope = kNone where no lobe lies below
  int sdm_steps_per_period = kAutoSdmSteps;  // semi-discretization only; kAutoSdmSteps: autoSdmSteps per speed
  // ZOA only: Measured takes each axis's measured FRF where present (delta must be 0).
  DynamicsSource dynamics = DynamicsSource::Modal;
  int sdm_delay_order =
      kDefaultSdmDelayOrder;  // semi-discretization: degree of the delayed-state interpolation (sdm_model.h)
  int sdm_helix_slices = kExactHelixSlices;  // semi-discretization: SdmOptions::helix_slices
};

// Throws InvalidInput for semi-discretization with DynamicsSource::Measured (it needs a state-space
// model), besides the methods' own checks.
LobeDiagram computeLobes(const MillingSetup& setup, const std::vector<double>& speeds_rev_per_s,
                         const LobeSettings& settings, const JobControl& control = {});

}  // namespace mx
