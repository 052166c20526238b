#pragma once
// Zeroth-order approximation (ZOA) of the stability lobes (Altintas & Budak; Rubio et al. 2006,
// eq. 8-10), with the Rule 1.1 margin: chatter roots placed at s = -delta + i omega_c.
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
};

// Throws InvalidInput for delta >= smallest decay rate (the message names delta and the bound),
// or non-positive speeds.
LobeDiagram computeZoaLobes(const MillingSetup& setup, const std::vector<double>& speeds_rev_per_s,
                            const ZoaOptions& options, const JobControl& control = {});

// Single-mode closed form of the lowest nominal lobe (x mode only, delta = 0):
// b_min = 2 pi / (n_t K_t alpha_xx Re G_min), Re G_min = -1 / (4 k zeta (1 + zeta)).
double singleModeMinimumDepth(const MillingSetup& setup);

}  // namespace mx
