#pragma once
// Fit error of a receptance model: relative RMS of the complex difference over the band [%],
//   e = 100 sqrt( sum |H_fit - H|^2 / sum |H|^2 ).
#include <complex>
#include <vector>

namespace mx {

// Throws InvalidInput when the sizes differ; 0 for two empty vectors.
double fitErrorPercent(const std::vector<std::complex<double>>& measured,
                       const std::vector<std::complex<double>>& fitted);

}  // namespace mx
