#include "frf_interpolation.h"

#include <algorithm>

namespace mx::widgets {

std::optional<std::complex<double>> interpolateFrf(const std::vector<double>& grid_hz,
                                                   const std::vector<std::complex<double>>& h, double frequency_hz) {
  const std::size_t n = std::min(grid_hz.size(), h.size());
  if (n == 0 || frequency_hz < grid_hz.front() || frequency_hz > grid_hz[n - 1]) return std::nullopt;
  const auto end = grid_hz.begin() + static_cast<std::ptrdiff_t>(n);
  const auto upper = std::lower_bound(grid_hz.begin(), end, frequency_hz);
  const auto i = static_cast<std::size_t>(upper - grid_hz.begin());
  if (grid_hz[i] == frequency_hz || i == 0) return h[i];
  const double t = (frequency_hz - grid_hz[i - 1]) / (grid_hz[i] - grid_hz[i - 1]);
  return h[i - 1] + t * (h[i] - h[i - 1]);
}

}  // namespace mx::widgets
