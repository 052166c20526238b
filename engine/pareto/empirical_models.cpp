#include "pareto/empirical_models.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/invalid_input.h"

namespace mx {

double PowerLawModel::evaluate(double v, double b_mm, double st_mm) const {
  return k * std::pow(v, speed_exponent) * std::pow(b_mm, depth_exponent) * std::pow(st_mm, feed_exponent);
}

void PowerLawModel::validate(const std::string& name) const {
  auto fail = [&](const char* field, double value, const char* range) {
    std::ostringstream os;
    os << name << "." << field << " = " << value << ": must be " << range;
    throw InvalidInput(os.str());
  };
  if (!(std::isfinite(k) && k > 0.0)) fail("k", k, "a finite number > 0");
  const double limit = 10.0;
  if (!(std::abs(speed_exponent) <= limit)) fail("speed_exponent", speed_exponent, "in [-10, 10]");
  if (!(std::abs(depth_exponent) <= limit)) fail("depth_exponent", depth_exponent, "in [-10, 10]");
  if (!(std::abs(feed_exponent) <= limit)) fail("feed_exponent", feed_exponent, "in [-10, 10]");
}

double cuttingSpeedMPerMin(double diameter_m, double speed_rev_per_s) {
  return std::numbers::pi * diameter_m * speed_rev_per_s * 60.0;
}

}  // namespace mx
