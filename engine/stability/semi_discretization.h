#pragma once
// Milling stability by first-order semi-discretization (Insperger & Stepan 2002, IJNME 55:503-518;
// Insperger & Stepan 2004, IJNME 61:117-141) of the regenerative model of Rubio et al. 2006, section 2
// (eq. 1-7), linearised about the static chip. Model and step maps: stability/sdm_model.h.
// Stability: every Floquet multiplier mu of the tooth-period monodromy map has |mu| <= exp(-delta T)
// (Rule 1.1 margin; delta = 0 gives the nominal lobes).
// Accuracy: with the first-order delay interpolation (delay_order 1) the multiplier error is O(dt^2),
// dt = T/m, about (omega_c dt)^2 / 12: with m = 40 it moves b_lim by up to ~30 % at low speeds
// (Insperger benchmark, slot, 5000-12000 rpm, omega_c dt ~ 0.8). The default is the cubic delay
// interpolation (error ~ (omega_c dt)^4) with the steps chosen per speed (autoSdmSteps): within 1 % of
// the converged b_lim on that benchmark away from cusps (docs/performance.md).
#include <complex>
#include <vector>

#include "core/cancellation.h"
#include "core/invalid_input.h"
#include "model/milling_setup.h"
#include "stability/lobe_diagram.h"

namespace mx {

// steps_per_period = kAutoSdmSteps: m is chosen per speed by autoSdmSteps.
inline constexpr int kAutoSdmSteps = 0;
// Degrees of the delayed-state interpolation (sdm_model.h): 1 .. kMaxSdmDelayOrder.
inline constexpr int kMaxSdmDelayOrder = 3;
inline constexpr int kDefaultSdmDelayOrder = 3;
// helix_slices = kExactHelixSlices: the helix lag is integrated over the depth in closed form.
inline constexpr int kExactHelixSlices = 0;
inline constexpr int kMaxHelixSlices = 1000;

struct SdmOptions {
  int steps_per_period = kAutoSdmSteps;     // m: time steps per (mean) tooth period, or kAutoSdmSteps
  int delay_order = kDefaultSdmDelayOrder;  // p: degree of the delayed-state interpolation (sdm_model.h)
  // Helical edges: kExactHelixSlices integrates the lag over the depth exactly; n in [1, kMaxHelixSlices]
  // uses n midpoint slices (their error falls as 1/n^2; tests/stability/test_sdm_cutter_geometry.cpp).
  int helix_slices = kExactHelixSlices;
  double delta_per_s = 0.0;       // Rule 1.1 margin: stable iff every Floquet multiplier |mu| <= exp(-delta*T)
  double max_depth_m = 0.02;      // envelope entry = +inf (LobeDiagram::kNone) if no instability below this
  double depth_tolerance = 1e-3;  // relative tolerance on b_lim
};

// Steps per tooth period at one speed for the cubic delay interpolation, the largest of:
//   60 (the angular resolution of the coefficient H_i over the pitch);
//   omega_max T / 0.3: the delayed state is interpolated over at most 0.3 rad of the fastest mode's
//     oscillation (cubic error ~ 0.3^4 / 43, 2e-4 of the amplitude);
//   20 pitch / cut angle: at least 20 steps inside the cut of each tooth (the averaged coefficient H_i
//     resolves the immersion; a/D = 0.05 with 2 teeth needs 140);
// rounded up to a multiple of 10 (models are shared between speeds) and capped at 1000.
int autoSdmSteps(const MillingSetup& setup, double spindle_rev_per_s);

// Dominant Floquet multiplier modulus of the tooth-period monodromy map at (speed, depth).
double sdmSpectralRadius(const MillingSetup& setup, double spindle_rev_per_s, double depth_m, int steps_per_period,
                         int delay_order = 1);

// Dominant multiplier (largest modulus; of a conjugate pair the one with Im >= 0) and the chatter
// frequency of its Floquet mode (SdmMonodromy::chatterFrequencyHz). A flip (period-doubling)
// boundary has a real negative multiplier, a Hopf (secondary) boundary a complex pair.
struct SdmMultiplier {
  std::complex<double> value{0.0, 0.0};
  double chatter_hz = 0.0;
};
SdmMultiplier sdmDominantMultiplier(const MillingSetup& setup, double spindle_rev_per_s, double depth_m,
                                    int steps_per_period, int delay_order = 1);

// b_lim at each speed (the lower envelope: the smallest depth whose dominant multiplier reaches
// exp(-delta T)), the chatter frequency of that multiplier's Floquet mode, i.e. the principal value
// |arg mu| / (2 pi T) unfolded by the dominant harmonic k of the mode's periodic factor:
// f = |arg(mu) / (2 pi) + k| / T (0 where b_lim = kNone), and the minima (envelopeMinima).
// lobes stays empty. Throws InvalidInput for delta outside [0, smallestDecayRate), steps < 4,
// speeds <= 0, max_depth <= 0 or depth_tolerance outside (0, 0.1]; polls control between speeds
// (throws Cancelled) and reports the fraction of speeds done.
// Root search: continuation in speed with an island scan (stability/sdm_boundary.cpp).
LobeDiagram computeSdmLobes(const MillingSetup& setup, const std::vector<double>& speeds_rev_per_s,
                            const SdmOptions& options, const JobControl& control = {});

}  // namespace mx
