#pragma once
// The point of Q that minimises Gilbert's cost or time per part (pareto/machining_economics.h), with
// the tool life of the Pareto paper's Taylor model (TOL [min], eq. 10) and the MRR of eq. 11.
#include <cstddef>
#include <functional>
#include <optional>

#include "pareto/machining_economics.h"
#include "pareto/objective_table.h"

namespace mx {

PartEconomics pointEconomics(const MachiningEconomics& e, const ParetoPoint& p);

// Index into table.points() of the cheapest (or fastest) point passing `admit`; nullopt when none.
std::optional<std::size_t> cheapestPoint(const ObjectiveTable& table, const MachiningEconomics& e,
                                         EconomicObjective objective,
                                         const std::function<bool(const ParetoPoint&)>& admit);

}  // namespace mx
