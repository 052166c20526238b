#include "sdnrp/gp_models.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/invalid_input.h"

namespace mx {

double SdnrpModels::desiredForce(double ra_um) {
  if (!(ra_um > 0.0) || !std::isfinite(ra_um))
    throw InvalidInput("K1: Ra = " + std::to_string(ra_um) + " um: must be > 0");
  return 293.0 - 593.0 / std::sqrt(39.37 * ra_um);
}

double SdnrpModels::feedCommand(double F) {
  if (!(F > 0.0) || !std::isfinite(F)) throw InvalidInput("K2: F = " + std::to_string(F) + " N: must be > 0");
  return 25.4 * (189.0 - 5926160.0 / (F * F));
}

double SdnrpModels::speedCommand(double F) {
  const double arg = 30064193.0 - 2.28 * F * F * F;
  if (!(arg >= 0.0) || !std::isfinite(arg))
    throw InvalidInput("K3: F = " + std::to_string(F) + " N: must be <= 236.25 N (30064193 - 2.28 F^3 >= 0)");
  return std::sqrt(arg);
}

double SdnrpModels::cuttingForce(double n, double f) {
  if (!(f > 0.0) || !std::isfinite(f)) throw InvalidInput("K4: feed = " + std::to_string(f) + " mm/min: must be > 0");
  if (!(n >= 0.0) || !std::isfinite(n)) throw InvalidInput("K4: speed = " + std::to_string(n) + " rpm: must be >= 0");
  return 286.44 - 5.82e-10 * n * n * n - 8973.0 * std::log(0.039 * f) / f;
}

double SdnrpModels::roughness(double F) {
  if (!(F < 293.0) || !std::isfinite(F)) throw InvalidInput("K5: F = " + std::to_string(F) + " N: must be < 293 N");
  const double q = 593.0 / (293.0 - F);
  return 0.0254 * q * q;
}

double SdnrpModels::cuttingForceFeedSensitivity(double f) {
  return 8973.0 * (std::log(0.039 * f) - 1.0) / (f * f);
}

double SdnrpModels::turningFeed() {
  return std::numbers::e / 0.039;
}

}  // namespace mx
