#pragma once
// Least-squares frequency-domain estimate of the residues for given poles (Peeters et al. 2004,
// sec. 2.3; Heylen et al. 1997, sec. 4.5): linear least squares over the band of
//   H(w) = sum_r [ A_r / (i w - lambda_r) + conj(A_r) / (i w - conj(lambda_r)) ] + LR / (i w)^2 + UR
// for complex A_r, LR and UR (real unknowns: Re and Im of each). The modes follow from
// modeFromResidue (modal_pole.h): k_r = -w_r^2 / (2 w_d,r Im A_r).
#include <complex>
#include <vector>

#include "modal_fit/fit_model.h"
#include "modal_fit/frf_band.h"

namespace mx {

struct LsfdFit {
  std::vector<std::complex<double>> residues;  // A_r, one per pole
  ResidualTerms residuals;                     // LR, UR
};

// Poles in the upper half-plane (Im lambda > 0), one per mode.
LsfdFit fitResidues(const FrfBand& band, const std::vector<std::complex<double>>& poles);

// The modes of an LSFD fit (modal_pole.h), in the order of the poles.
FittedModel fittedModel(const std::vector<std::complex<double>>& poles, const LsfdFit& fit);

}  // namespace mx
