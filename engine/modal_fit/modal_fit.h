#pragma once
// Modal parameters fitted to a measured receptance FRF (docs/measured-dynamics-fitting.md).
//   Lscf: LSCF stabilisation diagram over orders 2 .. 2 max_modes (lscf_diagram.h), the poles stable
//         over 3 consecutive orders or frequency-stable over 4 (stabilisation.h), the significant
//         ones (mode_selection.h), LSFD residues with residual terms (lsfd.h), nonlinear
//         least-squares refinement (nlls_refinement.h); automatic selection drops refined modes that
//         are insignificant or duplicates and fits the rest again.
//   Peak: peak picking with the half-power bandwidth (peak_picking.h), no residual terms.
#include <complex>
#include <string>
#include <vector>

#include "core/cancellation.h"
#include "modal_fit/fit_model.h"
#include "modal_fit/fit_settings.h"
#include "modal_fit/stabilisation.h"
#include "model/modal_model.h"

namespace mx {

inline constexpr int kMinStableOrders = 3;

struct ModalFitResult {
  ModalAxis modes;                           // sorted by frequency
  ResidualTerms residuals;                   // zero for peak picking
  double fit_error_pct = 0.0;                // fit_error.h, over the band
  std::string method;                        // the steps that ran
  StabilisationDiagram diagram;              // empty for peak picking
  std::vector<double> band_frequency_hz;     // the band's points (f > 0)
  std::vector<std::complex<double>> fitted;  // the model at band_frequency_hz [m/N]
};

// Fewer modes than settings.modes when fewer stable physical poles (or peaks) are found.
// Throws InvalidInput for bad data or settings (fit_settings.h), Cancelled when job is cancelled;
// reports progress over the LSCF orders (up to 0.8), then the residues and the refinement.
ModalFitResult fitModes(const std::vector<double>& frequency_hz, const std::vector<std::complex<double>>& h_m_per_n,
                        const ModalFitSettings& settings, const JobControl& job = {});

// The modes at the given poles (upper half-plane, e.g. picked on the stabilisation diagram): LSFD
// residues with residual terms, then the NLLS refinement when settings.refine. settings.modes,
// max_modes and method are ignored; the band is [from_hz, to_hz]; the returned diagram is empty.
// Throws InvalidInput for an empty pole list or a pole outside the band (naming it), and as fitModes
// for bad data.
ModalFitResult fitModesAtPoles(const std::vector<double>& frequency_hz,
                               const std::vector<std::complex<double>>& h_m_per_n, const ModalFitSettings& settings,
                               const std::vector<std::complex<double>>& poles, const JobControl& job = {});

}  // namespace mx
