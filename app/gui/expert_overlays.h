#pragma once
// Chart overlays derived from the expert session (2006 paper, section 3): the cost heat map of one tool over the
// (N, b) plane and its admissible grid points, in rpm and mm.
#include <QVector>
#include <array>

#include "expert/expert_session.h"

namespace mx::gui {

struct CostMapData {
  QVector<double> speeds_rpm;
  QVector<double> depths_mm;
  QVector<double> cost;  // cost[i * depths + j]; NaN where (N_i, b_j) has no admissible feed
};

// Per (N, b) cell, the minimum of eq. 13 over the cell's admissible feeds.
CostMapData costMap(const ExpertSession& session, std::size_t tool, const std::array<double, 3>& c);

// The (N, b) cells of Q (each has at least one admissible feed).
void gridPoints(const ExpertSession& session, std::size_t tool, QVector<double>& speeds_rpm,
                QVector<double>& depths_mm);

}  // namespace mx::gui
