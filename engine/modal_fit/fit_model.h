#pragma once
// The fitted receptance model: modes (mx::receptance) plus the residual terms of the out-of-band modes
// (Ewins 2000, sec. 4.4): H(w) = sum_r G_r(i w) + lower / (i w)^2 + upper.
#include <complex>
#include <vector>

#include "model/modal_model.h"

namespace mx {

struct ResidualTerms {
  std::complex<double> lower{0.0, 0.0};  // modes below the band, mass-like [m/(N s^2)]
  std::complex<double> upper{0.0, 0.0};  // modes above the band, compliance [m/N]
};

struct FittedModel {
  ModalAxis modes;
  ResidualTerms residuals;
};

std::complex<double> fittedReceptance(const FittedModel& model, double frequency_hz);
std::vector<std::complex<double>> fittedReceptance(const FittedModel& model, const std::vector<double>& frequency_hz);

}  // namespace mx
