#pragma once
// Linear interpolation of a sampled FRF onto other frequencies, for residuals and sums of FRFs
// measured on different grids.
#include <complex>
#include <optional>
#include <vector>

namespace mx::widgets {

// H at frequency_hz by linear interpolation of the real and imaginary parts between the neighbouring
// lines of an increasing grid; nullopt outside [front, back] or for an empty grid.
std::optional<std::complex<double>> interpolateFrf(const std::vector<double>& grid_hz,
                                                   const std::vector<std::complex<double>>& h, double frequency_hz);

}  // namespace mx::widgets
