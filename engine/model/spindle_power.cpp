#include "model/spindle_power.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "core/invalid_input.h"

namespace mx {

namespace {

[[noreturn]] void reject(const std::string& field, double value, const char* range) {
  std::ostringstream out;
  out << "spindle power: " << field << " = " << value << ": must be " << range;
  throw InvalidInput(out.str());
}

std::string rowField(std::size_t i, const char* name) {
  return "curve[" + std::to_string(i) + "]." + name;
}

// The curve's power at speed n (linear between rows, constant torque below the first, flat above the last).
double curvePower(const std::vector<SpindlePowerPoint>& curve, double n) {
  const SpindlePowerPoint& first = curve.front();
  if (n <= first.speed_rev_per_s)
    return first.speed_rev_per_s > 0.0 ? first.power_w * n / first.speed_rev_per_s : first.power_w;
  if (n >= curve.back().speed_rev_per_s) return curve.back().power_w;
  const auto upper = std::upper_bound(curve.begin(), curve.end(), n, [](double speed, const SpindlePowerPoint& p) {
    return speed < p.speed_rev_per_s;
  });
  const SpindlePowerPoint& a = *(upper - 1);
  const SpindlePowerPoint& b = *upper;
  const double t = (n - a.speed_rev_per_s) / (b.speed_rev_per_s - a.speed_rev_per_s);
  return a.power_w + t * (b.power_w - a.power_w);
}

}  // namespace

void SpindlePowerCurve::validate() const {
  if (!(max_power_w > 0.0)) reject("max_power_w", max_power_w, "> 0 (+inf: no limit)");
  if (!(max_torque_nm > 0.0)) reject("max_torque_nm", max_torque_nm, "> 0 (+inf: no limit)");
  if (curve.size() == 1) reject("curve size", 1.0, "0 or >= 2 rows");
  for (std::size_t i = 0; i < curve.size(); ++i) {
    const SpindlePowerPoint& p = curve[i];
    if (!(std::isfinite(p.speed_rev_per_s) && p.speed_rev_per_s >= 0.0))
      reject(rowField(i, "speed_rev_per_s"), p.speed_rev_per_s, "finite and >= 0");
    if (i > 0 && !(p.speed_rev_per_s > curve[i - 1].speed_rev_per_s))
      reject(rowField(i, "speed_rev_per_s"), p.speed_rev_per_s, "> the previous row's speed");
    if (!(std::isfinite(p.power_w) && p.power_w >= 0.0)) reject(rowField(i, "power_w"), p.power_w, "finite and >= 0");
  }
}

double SpindlePowerCurve::available(double speed_rev_per_s) const {
  const double n = std::max(speed_rev_per_s, 0.0);
  double p = max_power_w;
  if (std::isfinite(max_torque_nm)) p = std::min(p, 2.0 * std::numbers::pi * n * max_torque_nm);
  if (!curve.empty()) p = std::min(p, curvePower(curve, n));
  return p;
}

}  // namespace mx
