#include "expert/tool_cost.h"

#include <algorithm>
#include <cmath>

namespace mx {

namespace {
// -1: a clearly below b, +1 clearly above, 0 within the relative tolerance.
int compareWithTolerance(double a, double b) {
  const double tol = kCostTieTolerance * std::max(std::abs(a), std::abs(b));
  if (a < b - tol) return -1;
  if (a > b + tol) return 1;
  return 0;
}
}  // namespace

CostTerms toolCostTerms(const std::array<double, 3>& c, const CostNormalisation& nf, double power_w,
                        double mrr_m3_per_s, double speed_security) {
  CostTerms t;
  t.power = std::isfinite(nf.available_power_w) ? c[0] * power_w / nf.available_power_w : 0.0;
  t.mrr = c[1] * nf.max_mrr_m3_per_s / mrr_m3_per_s;
  t.speed_security = c[2] * nf.max_speed_security / speed_security;
  return t;
}

bool rankBefore(const RankKey& a, const RankKey& b) {
  if (const int c = compareWithTolerance(a.cost, b.cost)) return c < 0;
  if (const int c = compareWithTolerance(a.mrr, b.mrr)) return c > 0;
  if (const int c = compareWithTolerance(a.power, b.power)) return c < 0;
  if (const int c = compareWithTolerance(a.speed, b.speed)) return c < 0;
  if (const int c = compareWithTolerance(a.depth, b.depth)) return c < 0;
  return false;
}

}  // namespace mx
