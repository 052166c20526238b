#pragma once
// Zeroth-order approximation (ZOA) of the stability lobes (Altintas & Budak; Rubio et al. 2006,
// eq. 8-10), with the Rule 1.1 margin: chatter roots placed at s = -delta + i omega_c.
// Cutter geometry: unequal pitches change the delays only and take the variable-pitch path
// (zoa_variable_pitch.h). The helix drops out: the directional factors are averaged over a revolution,
// and every axial slice sweeps the same immersion whatever its lag. Runout changes the static chip only;
// the linearised regenerative equation does not contain it (as long as every tooth keeps cutting), so it
// does not change the lobes. Where the ZOA is accurate (a continuous cut, large radial immersion):
// zoa_validity.h.
#include <vector>

#include "core/cancellation.h"
#include "core/invalid_input.h"
#include "model/milling_setup.h"
#include "stability/lobe_diagram.h"

namespace mx {

struct ZoaOptions {
  double delta_per_s = 0.0;      // Rule 1.1; must stay below the smallest modal decay rate
  double max_depth_m = 0.02;     // envelope = kNone where no lobe lies below this depth
  int lobe_count = 0;            // number of lobes k = 0..count-1; 0 = enough to cover the lowest speed
  int frequency_samples = 1200;  // chatter-frequency samples (plus a dense band around every mode)
  // Measured: each axis uses setup.measured_x / measured_y where present, else its modes.
  DynamicsSource dynamics = DynamicsSource::Modal;
  int measured_subdivisions = 9;  // at most this many extra frequencies between two lines where |dH| > 1 % max|H|
};

// Uses computeZoaLobesAnyPitch when !setup.uniformPitch(); its lobes are then empty.
// Throws InvalidInput for an invalid geometry (MillingSetup::validateGeometry), delta >= smallest decay rate (the
// message names delta and the bound), non-positive speeds, delta != 0 with DynamicsSource::Measured (a measured FRF
// gives G(i omega) only), or an invalid measured FRF (MeasuredAxis::validate, named "measured_x" / "measured_y").
LobeDiagram computeZoaLobes(const MillingSetup& setup, const std::vector<double>& speeds_rev_per_s,
                            const ZoaOptions& options, const JobControl& control = {});

// Single-mode closed form of the lowest nominal lobe (x mode only, delta = 0):
// b_min = 2 pi / (n_t K_t alpha_xx Re G_min), Re G_min = -1 / (4 k zeta (1 + zeta)).
double singleModeMinimumDepth(const MillingSetup& setup);

}  // namespace mx
