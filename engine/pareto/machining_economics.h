#pragma once
// Classical machining economics (Gilbert 1950) on the Pareto paper's Taylor model (eq. 10): for a part
// that needs `removal_volume` of material removed at MRR with tool life T,
//   machining time   t_m = V / MRR
//   tool changes     n_t = t_m / T   (a fraction: the tool wears over several parts)
//   time per part    t_p = t_m + n_t t_ct
//   cost per part    C_p = M t_p + n_t C_t
// with M the machine rate, t_ct the tool-change time and C_t the cost of one tool life. Handling time
// per part is a constant and does not move the optimum, so it is left out. SI: s, m^3, currency/s.
//
// With a Taylor tool life T = K V^a (a < -1) and MRR proportional to V (b, s_t fixed), the minimum of
// C_p over V lies at T = (-a - 1)(t_ct + C_t / M) and the minimum of t_p at T = (-a - 1) t_ct
// (Gilbert's optimal tool lives; with a = -1/n these are the textbook (1/n - 1)(...)).
#include <optional>

namespace mx {

struct MachiningEconomics {
  double machine_rate_per_s = 0.0;  // M, currency per second
  double tool_cost = 0.0;           // C_t, currency per tool life
  double tool_change_s = 0.0;       // t_ct
  double removal_volume_m3 = 0.0;   // V per part

  // Throws InvalidInput naming the field when a value is negative, not finite, V <= 0, or M = C_t = 0.
  void validate() const;
};

struct PartEconomics {
  double machining_time_s = 0.0;
  double tool_changes = 0.0;  // per part
  double time_per_part_s = 0.0;
  double cost_per_part = 0.0;
};

enum class EconomicObjective { MinCost, MaxRate };

// tool_life_s <= 0 or mrr <= 0 give +inf times and costs.
PartEconomics partEconomics(const MachiningEconomics& e, double mrr_m3_per_s, double tool_life_s);

// The value minimised by `objective`: cost per part or time per part [s].
double economicCost(const PartEconomics& p, EconomicObjective objective);

// Gilbert's optimal tool life [s] for the Taylor speed exponent a (T proportional to V^a); nullopt
// when a >= -1 (no interior optimum: the fastest speed wins) or the minimum-cost life is unbounded
// (machine rate 0).
std::optional<double> gilbertToolLife(const MachiningEconomics& e, double speed_exponent, EconomicObjective objective);

}  // namespace mx
