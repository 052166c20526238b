#include "model/cutting_force.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mx {

namespace {
constexpr int kSamplesPerToothPeriod = 1440;

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

ToothForce toothForce(const MillingSetup& setup, double depth_m, double phi_rad, double chip_m) {
  if (chip_m <= 0.0 || !setup.immersion.contains(phi_rad)) return {};
  const double ft = setup.tangential_coefficient_pa * depth_m * chip_m;
  const double fr = setup.radial_ratio * ft;
  const double s = std::sin(phi_rad);
  const double c = std::cos(phi_rad);
  return {ft, -ft * c - fr * s, ft * s - fr * c};
}

double StaticForce::resultant() const {
  return std::hypot(fx_n, fy_n);
}

StaticForce staticForce(const MillingSetup& setup, const OperatingPoint& point, double theta_rad) {
  StaticForce total;
  const double pitch = setup.toothPitchRad();
  for (int j = 0; j < setup.teeth; ++j) {
    const double phi = theta_rad + j * pitch;
    const ToothForce f = toothForce(setup, point.axial_depth_m, phi, point.feed_per_tooth_m * std::sin(phi));
    total.tangential_sum_n += f.tangential_n;
    total.fx_n += f.fx_n;
    total.fy_n += f.fy_n;
  }
  return total;
}

CutPerformance evaluateCut(const MillingSetup& setup, const OperatingPoint& point) {
  CutPerformance out;
  out.cutting_speed_m_per_s = std::numbers::pi * setup.diameter_m * point.spindle_rev_per_s;
  double peak_tangential = 0.0;
  double sum_tangential = 0.0;
  const double pitch = setup.toothPitchRad();
  for (int i = 0; i < kSamplesPerToothPeriod; ++i) {
    const StaticForce f = staticForce(setup, point, pitch * i / kSamplesPerToothPeriod);
    peak_tangential = std::max(peak_tangential, f.tangential_sum_n);
    sum_tangential += f.tangential_sum_n;
    out.peak_force_n = std::max(out.peak_force_n, f.resultant());
  }
  out.peak_power_w = out.cutting_speed_m_per_s * peak_tangential;
  out.mean_power_w = out.cutting_speed_m_per_s * sum_tangential / kSamplesPerToothPeriod;
  out.peak_torque_nm = 0.5 * setup.diameter_m * peak_tangential;
  out.mrr_m3_per_s =
      setup.radial_depth_m * point.axial_depth_m * point.feed_per_tooth_m * setup.teeth * point.spindle_rev_per_s;
  return out;
}

double peakPowerPerDepthFeed(const MillingSetup& setup, double spindle_rev_per_s) {
  const OperatingPoint unit{spindle_rev_per_s, 1.0, 1.0};
  return evaluateCut(setup, unit).peak_power_w;
}

double peakForcePerDepthFeed(const MillingSetup& setup) {
  const OperatingPoint unit{1.0, 1.0, 1.0};
  return evaluateCut(setup, unit).peak_force_n;
}

}  // namespace mx
