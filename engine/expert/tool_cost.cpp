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

double powerCostTerm(double c1, double power_w, double available_power_w) {
  return std::isfinite(available_power_w) ? c1 * power_w / available_power_w : 0.0;
}

CostTerms toolCostTerms(const std::array<double, 3>& c, const CostNormalisation& nf, double speed_rev_per_s,
                        double power_w, double mrr_m3_per_s, double speed_security) {
  CostTerms t;
  t.power = powerCostTerm(c[0], power_w, nf.available_power.available(speed_rev_per_s));
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
