#include "pareto/machining_economics.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/invalid_input.h"

namespace mx {

namespace {
void requireNonNegative(const char* name, double v) {
  if (!std::isfinite(v) || v < 0.0)
    throw InvalidInput(std::string(name) + " = " + std::to_string(v) + ": must be a finite number >= 0");
}
}  // namespace

void MachiningEconomics::validate() const {
  requireNonNegative("machine_rate_per_s", machine_rate_per_s);
  requireNonNegative("tool_cost", tool_cost);
  requireNonNegative("tool_change_s", tool_change_s);
  if (!std::isfinite(removal_volume_m3) || removal_volume_m3 <= 0.0)
    throw InvalidInput("removal_volume_m3 = " + std::to_string(removal_volume_m3) + ": must be > 0");
  if (machine_rate_per_s == 0.0 && tool_cost == 0.0)
    throw InvalidInput("machine_rate_per_s = 0 and tool_cost = 0: at least one must be > 0");
}

PartEconomics partEconomics(const MachiningEconomics& e, double mrr, double tool_life_s) {
  PartEconomics p;
  if (!(mrr > 0.0) || !(tool_life_s > 0.0)) {
    const double inf = std::numeric_limits<double>::infinity();
    return {inf, inf, inf, inf};
  }
  p.machining_time_s = e.removal_volume_m3 / mrr;
  p.tool_changes = p.machining_time_s / tool_life_s;
  p.time_per_part_s = p.machining_time_s + p.tool_changes * e.tool_change_s;
  p.cost_per_part = e.machine_rate_per_s * p.time_per_part_s + p.tool_changes * e.tool_cost;
  return p;
}

double economicCost(const PartEconomics& p, EconomicObjective objective) {
  return objective == EconomicObjective::MinCost ? p.cost_per_part : p.time_per_part_s;
}

std::optional<double> gilbertToolLife(const MachiningEconomics& e, double a, EconomicObjective objective) {
  if (!(a < -1.0)) return std::nullopt;
  if (objective == EconomicObjective::MaxRate) return (-a - 1.0) * e.tool_change_s;
  if (!(e.machine_rate_per_s > 0.0)) return std::nullopt;
  return (-a - 1.0) * (e.tool_change_s + e.tool_cost / e.machine_rate_per_s);
}

}  // namespace mx
