#include "expert_overlays.h"

#include <cmath>
#include <limits>

#include "expert/tool_cost.h"

namespace mx::gui {

CostMapData costMap(const ExpertSession& session, std::size_t tool, const std::array<double, 3>& c) {
  CostMapData out;
  const AdmissibleGrid& grid = session.grid(tool);
  if (grid.empty()) return out;
  const double step = grid.depthStep();
  int max_j = 0;
  for (const GridCell& cell : grid.cells()) max_j = std::max(max_j, static_cast<int>(std::lround(cell.depth_m / step)));
  for (double n : grid.speeds()) out.speeds_rpm.push_back(revPerSToRpm(n));
  for (int j = 1; j <= max_j; ++j) out.depths_mm.push_back(j * step * 1e3);
  const qsizetype depths = out.depths_mm.size();
  out.cost.fill(std::numeric_limits<double>::quiet_NaN(), out.speeds_rpm.size() * depths);
  const auto& speeds = grid.speeds();
  std::size_t i = 0;
  for (const GridCell& cell : grid.cells()) {
    while (i < speeds.size() && speeds[i] < cell.speed_rev_per_s * (1.0 - 1e-12)) ++i;
    const qsizetype j = std::lround(cell.depth_m / step) - 1;
    if (i >= speeds.size() || j < 0 || j >= depths) continue;
    double best = std::numeric_limits<double>::infinity();
    for (int f = 1; f <= cell.feed_count; ++f) {
      const double s = f * grid.feedStep();
      best = std::min(best, toolCostTerms(c, session.normalisation(), cell.speed_rev_per_s,
                                          cell.power_at_zero_feed_w + cell.power_per_feed * s, cell.mrr_per_feed * s,
                                          cell.speed_security)
                                .total());
    }
    out.cost[static_cast<qsizetype>(i) * depths + j] = best;
  }
  return out;
}

void gridPoints(const ExpertSession& session, std::size_t tool, QVector<double>& speeds_rpm,
                QVector<double>& depths_mm) {
  speeds_rpm.clear();
  depths_mm.clear();
  for (const GridCell& cell : session.grid(tool).cells()) {
    speeds_rpm.push_back(revPerSToRpm(cell.speed_rev_per_s));
    depths_mm.push_back(cell.depth_m * 1e3);
  }
}

}  // namespace mx::gui
