#pragma once
// Automatic choice of the modes among the stable poles (Peeters et al. 2004, sec. 3): a pole is kept when
// its LSFD residue (lsfd.h) gives a physical mode (k > 0, 0 < zeta < max_damping) that is significant:
// its resonance amplitude 1 / (2 zeta k) is at least min_significance of the measured |H| at its
// frequency. The kept poles are ranked by that amplitude; `modes` (when given) or max_modes of them stay.
#include <complex>
#include <optional>
#include <vector>

#include "modal_fit/frf_band.h"
#include "model/modal_model.h"

namespace mx {

struct SelectionCriteria {
  double min_significance = 0.1;
  double max_damping = 0.3;
};

double resonanceAmplitude(const Mode& mode);                 // 1 / (2 zeta k) [m/N]
double significance(const FrfBand& band, const Mode& mode);  // amplitude / measured |H| nearest f_n

// The physical and significant ones of `modes`, in their order.
ModalAxis significantModes(const FrfBand& band, const ModalAxis& modes, const SelectionCriteria& criteria = {});

// Of two modes closer in frequency than a quarter of the lighter-damped one's half-power bandwidth,
// zeta f / 2, the one with the larger resonance amplitude; sorted by frequency.
ModalAxis distinctModes(const ModalAxis& modes);

// With `modes` given the significance threshold is not applied: the `modes` largest physical ones stay.
std::vector<std::complex<double>> selectPoles(const FrfBand& band, const std::vector<std::complex<double>>& poles,
                                              std::optional<int> modes, int max_modes,
                                              const SelectionCriteria& criteria = {});

}  // namespace mx
