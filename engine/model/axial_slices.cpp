#include "model/axial_slices.h"

#include <algorithm>
#include <cmath>

namespace mx {

int defaultAxialSlices(const MillingSetup& setup, double depth_m) {
  const double lag = std::abs(setup.helixLagRad(depth_m));
  if (!(lag > 0.0)) return 1;
  return static_cast<int>(std::clamp(std::ceil(lag / kMaxSliceLagRad), 1.0, double(kMaxAxialSlices)));
}

std::vector<AxialSlice> axialSlices(const MillingSetup& setup, double depth_m, int slices) {
  const int n = slices > 0 ? slices : defaultAxialSlices(setup, depth_m);
  std::vector<AxialSlice> out(static_cast<std::size_t>(n));
  const double dz = depth_m / n;
  for (int k = 0; k < n; ++k) out[static_cast<std::size_t>(k)] = {setup.helixLagRad((k + 0.5) * dz), dz};
  return out;
}

}  // namespace mx
