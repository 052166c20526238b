#pragma once
// The 2006 tool cost function (eq. 13) and the deterministic order of candidate points.
//   C = c1 P / P_av + c2 MRR_max / MRR + c3 Delta N_s,max / Delta N_s
// NF1 = 1 / P_av (available spindle power at the point's speed: torque-limited below the spindle's
// base speed), NF2 = MRR_max and NF3 = Delta N_s,max over the admissible points of all candidate tools. Lower is
// better. Delta N_s = 0 points are not admissible, so the third term is always finite.
#include <array>

#include "model/spindle_power.h"

namespace mx {

struct CostNormalisation {
  SpindlePowerCurve available_power;  // P_av(N) (+inf: the power term vanishes)
  double max_mrr_m3_per_s = 0.0;      // NF2
  double max_speed_security = 0.0;    // NF3 [rev/s]
};

struct CostTerms {
  double power = 0.0;           // c1 P / P_av
  double mrr = 0.0;             // c2 MRR_max / MRR
  double speed_security = 0.0;  // c3 Delta N_s,max / Delta N_s
  double total() const { return power + mrr + speed_security; }
};

// The terms at a point of speed speed_rev_per_s (P_av is taken there).
CostTerms toolCostTerms(const std::array<double, 3>& c, const CostNormalisation& nf, double speed_rev_per_s,
                        double power_w, double mrr_m3_per_s, double speed_security);
// c1 P / P_av with P_av = available_power_w; 0 when P_av is +inf.
double powerCostTerm(double c1, double power_w, double available_power_w);

// Candidate order (Rule 4 and q*): lower cost; costs within kCostTieTolerance (relative) are a tie,
// broken by higher MRR, then lower power, then lower speed, then lower depth (each compared with the
// same relative tolerance; exact equality of everything keeps the earlier candidate).
inline constexpr double kCostTieTolerance = 1e-9;

struct RankKey {
  double cost = 0.0;
  double mrr = 0.0;
  double power = 0.0;
  double speed = 0.0;
  double depth = 0.0;
};

// True when a is strictly preferred to b.
bool rankBefore(const RankKey& a, const RankKey& b);

}  // namespace mx
