#pragma once
// The axial depth of cut divided into slices for a helical cutter (Altintas 2000, sec. 3.3): slice k of
// n spans heights [k b/n, (k + 1) b/n] and is represented by its mid-height, where the edge lags the tip
// by helixLagRad(z_k). Straight teeth need one slice.
#include <numbers>
#include <vector>

#include "model/milling_setup.h"

namespace mx {

struct AxialSlice {
  double lag_rad = 0.0;  // the edge's angle behind the tool tip at the slice's mid-height
  double depth_m = 0.0;  // the slice's axial thickness
};

// The slice count for which the lag across one slice is at most kMaxSliceLagRad: the static forces'
// peak then differs from four times as many slices by about 0.2 % (model.cutting_force).
inline constexpr double kMaxSliceLagRad = std::numbers::pi / 180.0;
inline constexpr int kMaxAxialSlices = 720;
int defaultAxialSlices(const MillingSetup& setup, double depth_m);

// `slices` >= 1 equal slices of [0, depth_m]; 0 chooses defaultAxialSlices.
std::vector<AxialSlice> axialSlices(const MillingSetup& setup, double depth_m, int slices = 0);

}  // namespace mx
