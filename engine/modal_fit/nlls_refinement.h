#pragma once
// Nonlinear least-squares refinement of a fitted receptance model (Levenberg-Marquardt, MINPACK lmder
// in Eigen's unsupported NonLinearOptimization): minimises sum_k |H_fit(w_k) - H_k|^2 over the band in
// (f_n, zeta, 1/k) of every mode and the complex residual terms, starting from an LSFD model. With
// G = w^2 c / D, D = s^2 + 2 zeta w s + w^2, c = 1/k, s = i w_k, the analytic Jacobian is
//   dG/dw = 2 w c s (s + zeta w) / D^2,   dG/dzeta = -2 w^3 c s / D^2,   dG/dc = w^2 / D.
#include "core/cancellation.h"
#include "modal_fit/fit_model.h"
#include "modal_fit/frf_band.h"

namespace mx {

// The refined model, or `start` when the refinement leaves the physical domain (f > 0, 0 < zeta < 1,
// k > 0) or does not lower the cost. Stops early (returning `start`) when job is cancelled.
FittedModel refineModel(const FrfBand& band, const FittedModel& start, const JobControl& job = {});

}  // namespace mx
