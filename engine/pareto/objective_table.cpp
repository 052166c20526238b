#include "pareto/objective_table.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/cutting_force.h"

namespace mx {

namespace {
ParetoPoint makePoint(const MillingSetup& setup, const ParetoModels& m, double n, double b, double s, double power,
                      double mrr, double ros) {
  ParetoPoint p;
  p.speed_rev_per_s = n;
  p.depth_m = b;
  p.feed_per_tooth_m = s;
  p.power_w = power;
  const double v = cuttingSpeedMPerMin(setup.diameter_m, n);
  p.objectives[index(Objective::ToolLife)] = m.tool_life.evaluate(v, b * 1e3, s * 1e3);
  p.objectives[index(Objective::Mrr)] = mrr;
  p.objectives[index(Objective::Roughness)] = m.roughness.evaluate(v, b * 1e3, s * 1e3);
  p.objectives[index(Objective::Robustness)] = ros;
  return p;
}
}  // namespace

ObjectiveTable::ObjectiveTable(const AdmissibleGrid& grid, const ParetoModels& models,
                               ParetoNormalisation normalisation)
    : grid_(&grid), models_(models), normalisation_(normalisation) {
  models_.tool_life.validate("taylor");
  models_.roughness.validate("roughness");
  const std::vector<GridCell>& cells = grid.cells();
  if (cells.empty()) return;
  std::size_t count = 0;
  for (const GridCell& c : cells) count += static_cast<std::size_t>(c.feed_count);

  points_.reserve(count);
  for (std::size_t ci = 0; ci < cells.size(); ++ci) {
    const GridCell& c = cells[ci];
    const double ros = grid.boundary().robustness(c.speed_rev_per_s, c.depth_m);
    for (int f = 1; f <= c.feed_count; ++f) {
      const ExpertPoint q = grid.point(ci, f);
      points_.push_back(makePoint(grid.setup(), models_, q.speed_rev_per_s, q.depth_m, q.feed_per_tooth_m, q.power_w,
                                  q.mrr_m3_per_s, ros));
    }
  }
  range_.min.fill(std::numeric_limits<double>::infinity());
  range_.max.fill(-std::numeric_limits<double>::infinity());
  for (const ParetoPoint& p : points_)
    for (std::size_t i = 0; i < kObjectiveCount; ++i) {
      range_.min[i] = std::min(range_.min[i], p.objectives[i]);
      range_.max[i] = std::max(range_.max[i], p.objectives[i]);
    }
  scores_.reserve(points_.size());
  for (const ParetoPoint& p : points_) scores_.push_back(normalise(p.objectives));
}

ParetoPoint ObjectiveTable::evaluate(double n, double b, double s, std::optional<double> ros) const {
  const CutPerformance perf = evaluateCut(grid_->setup(), {n, b, s});
  if (!ros) ros = grid_->boundary().robustness(n, b);
  return makePoint(grid_->setup(), models_, n, b, s, perf.peak_power_w, perf.mrr_m3_per_s, *ros);
}

ObjectiveVector ObjectiveTable::normalise(const ObjectiveVector& raw) const {
  ObjectiveVector out{};
  for (std::size_t i = 0; i < kObjectiveCount; ++i) out[i] = normaliseOne(i, raw[i]);
  return out;
}

double ObjectiveTable::normaliseOne(std::size_t i, double x) const {
  const double lo = range_.min[i], hi = range_.max[i];
  if (!(hi > lo)) return 1.0;
  const bool power_law = i == index(Objective::ToolLife) || i == index(Objective::Roughness);
  switch (normalisation_) {
    case ParetoNormalisation::Max:
      if (!(hi > 0.0)) return 1.0;
      return isMinimised(i) ? 1.0 - x / hi : x / hi;
    case ParetoNormalisation::Log:
      if (power_law && lo > 0.0) {
        const double t = std::log(x / lo) / std::log(hi / lo);
        return isMinimised(i) ? 1.0 - t : t;
      }
      break;
    case ParetoNormalisation::MinMax:
      break;
  }
  return isMinimised(i) ? (hi - x) / (hi - lo) : (x - lo) / (hi - lo);
}

}  // namespace mx
