#include "simulation/cutter_edges.h"

#include <algorithm>
#include <numbers>

#include "model/axial_slices.h"

namespace mx {

bool teethSharePasses(const MillingSetup& setup) {
  return setup.uniformPitch() && !setup.hasRunout();
}

namespace {
// Uniform teeth at exactly j pitch (a pitch list equal to the mean within 1e-9 rad counts as uniform).
double toothAngle(const MillingSetup& setup, int tooth) {
  return setup.uniformPitch() ? tooth * setup.toothPitchRad() : setup.toothAngleRad(tooth);
}
}  // namespace

std::vector<CutterEdge> cutterEdges(const MillingSetup& setup, double depth_m, int slices) {
  const bool shared = teethSharePasses(setup);
  const std::vector<AxialSlice> axial = axialSlices(setup, depth_m, slices);
  const double fraction = 1.0 / static_cast<double>(axial.size());
  std::vector<CutterEdge> edges;
  edges.reserve(axial.size() * static_cast<std::size_t>(setup.teeth));
  for (int j = 0; j < setup.teeth; ++j) {
    for (const AxialSlice& slice : axial)
      edges.push_back({toothAngle(setup, j) - slice.lag_rad, fraction, shared ? 0 : j});
  }
  return edges;
}

std::vector<CutterEdge> straightTeeth(const MillingSetup& setup) {
  const bool shared = teethSharePasses(setup);
  std::vector<CutterEdge> edges;
  edges.reserve(static_cast<std::size_t>(setup.teeth));
  for (int j = 0; j < setup.teeth; ++j) edges.push_back({toothAngle(setup, j), 1.0, shared ? 0 : j});
  return edges;
}

double ToothPasses::maxDelayToothPeriods() const {
  return delay_tooth_periods.empty() ? 0.0 : *std::max_element(delay_tooth_periods.begin(), delay_tooth_periods.end());
}

ToothPasses toothPasses(const MillingSetup& setup, double feed_per_tooth_m, int passes) {
  ToothPasses out;
  out.sets = teethSharePasses(setup) ? 1 : setup.teeth;
  out.passes = passes;
  const std::size_t size = static_cast<std::size_t>(out.sets) * static_cast<std::size_t>(passes);
  out.delay_tooth_periods.resize(size);
  out.feed_m.resize(size);
  out.runout_m.resize(size);
  const double teeth_per_radian = setup.teeth / (2.0 * std::numbers::pi);
  for (int j = 0; j < out.sets; ++j) {
    double turned = 0.0;  // A_jk
    for (int k = 0; k < passes; ++k) {
      const std::size_t i = out.index(j, k);
      const int ahead = (j + k + 1) % setup.teeth;  // the tooth that left the surface
      if (out.sets == 1) {
        out.delay_tooth_periods[i] = k + 1;
      } else {
        turned += setup.pitchRad((j + k) % setup.teeth);
        out.delay_tooth_periods[i] = setup.uniformPitch() ? k + 1.0 : turned * teeth_per_radian;
      }
      out.feed_m[i] = out.delay_tooth_periods[i] * feed_per_tooth_m;
      out.runout_m[i] = setup.runoutM(j) - setup.runoutM(ahead);
    }
  }
  return out;
}

ToothPasses rigidToolPasses(const MillingSetup& setup, double feed_per_tooth_m) {
  return toothPasses(setup, feed_per_tooth_m, teethSharePasses(setup) ? 1 : setup.teeth);
}

}  // namespace mx
