#pragma once
// Peak picking with the half-power bandwidth on |H| (Ewins 2000, sec. 4.3): a quick single-mode
// estimate per resonance, accurate for light damping and well-separated modes.
//   f_n   at the local maximum of |H| (vertex of the parabola through the three samples around it),
//   zeta  = (f_2 - f_1) / (2 f_n), f_1 < f_n < f_2 the -3 dB crossings |H| = |H|max / sqrt(2),
//         each interpolated linearly between the samples that bracket it,
//   k     = 1 / (2 zeta |H|max)   (|H(w_n)| = 1 / (2 zeta k) for one mode).
#include <cmath>

#include "modal_fit/frf_band.h"
#include "model/modal_model.h"

namespace mx {

// Local maxima whose prominence (peak / the higher of the lowest |H| on either side before a higher
// sample or the band's end) exceeds min_prominence (> sqrt(2), so both crossings exist). Returns the
// max_peaks highest, sorted by frequency.
ModalAxis pickPeaks(const FrfBand& band, int max_peaks, double min_prominence = 1.5);

}  // namespace mx
