#pragma once
// Zeroth-order stability of variable-pitch cutters (Altintas, Engin & Budak 1999, J. Manuf. Sci. Eng.
// 121:173-178). Every tooth sweeps the same immersion, so the per-tooth directional matrix [A0] averaged
// over a revolution is the uniform one (averageDirectionalFactors, Budak & Altintas 1998); only the delays differ,
// tau_j = pitchRad(j) / Omega. With the Rule 1.1 margin, roots at s = -delta + i omega:
//   det[I - (K_t b / 4 pi) S(s) [A0][G(s)]] = 0,   S(s) = sum_j (1 - e^{-s tau_j}),
// which is the uniform equation (S = n_t (1 - e^{-s T})) for equal pitches. The speed no longer follows
// from the phase in closed form, so each requested speed is solved on its own: along the chatter
// frequency, each eigenvalue mu(omega) of [A0][G] gives u = 1/b = K_t S mu / 4 pi; the boundary is where
// Im u = 0 with Re u > 0 (a real positive depth), and b_lim is the smallest such b.
#include <complex>
#include <vector>

#include "core/cancellation.h"
#include "model/milling_setup.h"
#include "stability/lobe_diagram.h"
#include "stability/zero_order_lobes.h"

namespace mx {

// S(s) = sum_j (1 - e^{-s pitchRad(j) / Omega}), Omega = 2 pi spindle_rev_per_s.
std::complex<double> regenerativePitchSum(const MillingSetup& setup, double spindle_rev_per_s, std::complex<double> s);

// The ZOA lobes of any pitch, uniform included (computeZoaLobes takes this path when !uniformPitch()).
// Per speed: the envelope depth (kNone above options.max_depth_m) and its chatter frequency; the minima
// (envelopeMinima). lobes stays empty: with unequal delays there is no lobe index k (eq. 9) and no curve
// to follow. options.lobe_count is not used. Chatter-frequency scan: zoaChatterFrequencyGrid, subdivided
// per speed to at least 16 samples per period 2 pi / tau_max of the longest delay term; each sign change
// of Im u is refined by the Illinois method to 1e-12 in omega. Throws as computeZoaLobes, plus
// MillingSetup::validateGeometry; polls control between speeds (throws Cancelled) and reports the
// fraction of speeds done.
LobeDiagram computeZoaLobesAnyPitch(const MillingSetup& setup, const std::vector<double>& speeds_rev_per_s,
                                    const ZoaOptions& options, const JobControl& control = {});

}  // namespace mx
