#include "pareto/economic_selection.h"

#include <limits>

namespace mx {

PartEconomics pointEconomics(const MachiningEconomics& e, const ParetoPoint& p) {
  return partEconomics(e, p.mrr(), p.tol() * 60.0);
}

std::optional<std::size_t> cheapestPoint(const ObjectiveTable& table, const MachiningEconomics& e,
                                         EconomicObjective objective,
                                         const std::function<bool(const ParetoPoint&)>& admit) {
  e.validate();
  std::optional<std::size_t> best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const ParetoPoint& p = table.points()[i];
    if (!admit(p)) continue;
    const double cost = economicCost(pointEconomics(e, p), objective);
    if (cost < best_cost) {
      best_cost = cost;
      best = i;
    }
  }
  return best;
}

}  // namespace mx
