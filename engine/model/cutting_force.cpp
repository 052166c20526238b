#include "model/cutting_force.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace mx {

namespace {
constexpr int kSamplesPerToothPeriod = 1440;
// Unequal teeth repeat once per revolution: 1440 samples per mean pitch up to 16 teeth, then 23040 per
// revolution (0.016 deg apart, over 200 per pitch of a 100-tooth face mill).
constexpr int kMaxSamplesPerRevolution = 16 * kSamplesPerToothPeriod;

// Antiderivatives of the directional factors (Altintas 2000, eq. 3.52), times 2.
DirectionalFactors primitive(double phi, double kr) {
  const double c2 = std::cos(2.0 * phi);
  const double s2 = std::sin(2.0 * phi);
  return {c2 - 2.0 * kr * phi + kr * s2, -s2 - 2.0 * phi + kr * c2, -s2 + 2.0 * phi + kr * c2,
          -c2 - 2.0 * kr * phi - kr * s2};
}
}  // namespace

DirectionalFactors averageDirectionalFactors(const Immersion& immersion, double radial_ratio) {
  const DirectionalFactors a = primitive(immersion.exit_rad, radial_ratio);
  const DirectionalFactors b = primitive(immersion.entry_rad, radial_ratio);
  return {0.5 * (a.xx - b.xx), 0.5 * (a.xy - b.xy), 0.5 * (a.yx - b.yx), 0.5 * (a.yy - b.yy)};
}

namespace {
ToothForce resolved(double ft, double fr, double fa, double phi_rad) {
  const double s = std::sin(phi_rad);
  const double c = std::cos(phi_rad);
  return {ft, -ft * c - fr * s, ft * s - fr * c, fa};
}
}  // namespace

ToothForce chipForcePerArea(const MillingSetup& setup, double phi_rad) {
  const double ft = setup.tangential_coefficient_pa;
  return resolved(ft, setup.radial_ratio * ft, setup.axial_coefficient_pa, phi_rad);
}

ToothForce edgeForcePerDepth(const MillingSetup& setup, double phi_rad) {
  return resolved(setup.tangential_edge_n_per_m, setup.radial_edge_n_per_m, setup.axial_edge_n_per_m, phi_rad);
}

ToothForce toothForce(const MillingSetup& setup, double depth_m, double phi_rad, double chip_m) {
  if (chip_m <= 0.0 || !setup.immersion.contains(phi_rad)) return {};
  const double kt = setup.tangential_coefficient_pa;
  const double ft = depth_m * (kt * chip_m + setup.tangential_edge_n_per_m);
  const double fr = depth_m * (setup.radial_ratio * kt * chip_m + setup.radial_edge_n_per_m);
  const double fa = depth_m * (setup.axial_coefficient_pa * chip_m + setup.axial_edge_n_per_m);
  return resolved(ft, fr, fa, phi_rad);
}

double StaticForce::resultant() const {
  return std::hypot(fx_n, fy_n);
}

StaticCut::StaticCut(const MillingSetup& setup, const OperatingPoint& point, int slices)
    : setup_(setup), feed_m_(point.feed_per_tooth_m), slices_(axialSlices(setup, point.axial_depth_m, slices)) {
  const int n = setup.teeth;
  // Without runout the nearest tooth ahead always leaves the thinnest chip (sin phi >= 0 in the cut).
  const int passes = setup.hasRunout() ? n : 1;
  for (int j = 0; j < n; ++j) {
    tooth_angle_.push_back(setup.toothAngleRad(j));
    std::vector<Pass> tooth;
    double pitch = 0.0;
    for (int k = 1; k <= passes; ++k) {
      pitch += setup.pitchRad((j + k - 1) % n);
      tooth.push_back({pitch * n / (2.0 * std::numbers::pi), setup.runoutM(j) - setup.runoutM((j + k) % n)});
    }
    double least = std::numeric_limits<double>::infinity();
    for (const Pass& p : tooth) least = std::min(least, p.runout_m);
    least_runout_m_.push_back(least);
    passes_.push_back(std::move(tooth));
  }
}

StaticForce StaticCut::at(double theta_rad) const {
  StaticForce total;
  for (std::size_t j = 0; j < tooth_angle_.size(); ++j) {
    for (const AxialSlice& slice : slices_) {
      const double phi = theta_rad + tooth_angle_[j] - slice.lag_rad;
      if (!setup_.immersion.contains(phi)) continue;
      const double s = std::sin(phi);
      double chip = std::numeric_limits<double>::infinity();
      // In the cut sin phi >= 0, so a later pass (a larger feed factor) leaves at least
      // s_t f s + the least runout: once that reaches the chip, no later pass can thin it.
      for (const Pass& pass : passes_[j]) {
        if (s >= 0.0 && feed_m_ * pass.feed_factor * s + least_runout_m_[j] >= chip) break;
        chip = std::min(chip, feed_m_ * pass.feed_factor * s + pass.runout_m);
      }
      const ToothForce f = toothForce(setup_, slice.depth_m, phi, chip);
      total.tangential_sum_n += f.tangential_n;
      total.fx_n += f.fx_n;
      total.fy_n += f.fy_n;
      total.fz_n += f.fz_n;
    }
  }
  return total;
}

StaticForce staticForce(const MillingSetup& setup, const OperatingPoint& point, double theta_rad) {
  return StaticCut(setup, point).at(theta_rad);
}

CutPerformance evaluateCut(const MillingSetup& setup, const OperatingPoint& point) {
  CutPerformance out;
  out.cutting_speed_m_per_s = std::numbers::pi * setup.diameter_m * point.spindle_rev_per_s;
  double peak_tangential = 0.0;
  double sum_tangential = 0.0;
  const StaticCut cut(setup, point);
  // Unequal teeth (pitch or runout) repeat the force once per revolution, equal teeth once per pitch.
  const int period_teeth = setup.uniformPitch() && !setup.hasRunout() ? 1 : setup.teeth;
  const int samples = std::min(kSamplesPerToothPeriod * period_teeth, kMaxSamplesPerRevolution);
  const double period = setup.toothPitchRad() * period_teeth;
  for (int i = 0; i < samples; ++i) {
    const StaticForce f = cut.at(period * i / samples);
    peak_tangential = std::max(peak_tangential, f.tangential_sum_n);
    sum_tangential += f.tangential_sum_n;
    out.peak_force_n = std::max(out.peak_force_n, f.resultant());
    out.peak_axial_force_n = std::max(out.peak_axial_force_n, std::abs(f.fz_n));
  }
  out.peak_power_w = out.cutting_speed_m_per_s * peak_tangential;
  out.mean_power_w = out.cutting_speed_m_per_s * sum_tangential / samples;
  out.peak_torque_nm = 0.5 * setup.diameter_m * peak_tangential;
  out.mrr_m3_per_s =
      setup.radial_depth_m * point.axial_depth_m * point.feed_per_tooth_m * setup.teeth * point.spindle_rev_per_s;
  return out;
}

PeakPerDepthFeed peakPerDepthFeed(const MillingSetup& setup, double depth_m, double feed_m) {
  const CutPerformance perf = evaluateCut(setup, {1.0, depth_m, feed_m});
  const double area = depth_m * feed_m;
  return {perf.peak_power_w / area, perf.peak_force_n / area};
}

}  // namespace mx
