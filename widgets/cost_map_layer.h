#pragma once
// Expert overlays of the lobe chart (internal to LobeChartView): the tool-cost heat map over the
// (N, b) plane (2006 eq. 13, the minimum over the admissible feeds of each cell) and the admissible
// grid points. Lengths are handed over in display units.
#include <QString>
#include <QVector>

class QCustomPlot;
class QCPColorMap;
class QCPColorScale;
class QCPGraph;

namespace mx::widgets {

class CostMapLayer {
 public:
  explicit CostMapLayer(QCustomPlot* plot);

  // Regular grid: cost[i * depths.size() + j] at (speeds[i], depths[j]); NaN = not admissible.
  void setCostMap(const QVector<double>& speeds, const QVector<double>& depths, const QVector<double>& cost);
  void setGridPoints(const QVector<double>& speeds, const QVector<double>& depths);
  void setCostMapVisible(bool visible);
  void setGridVisible(bool visible);
  bool costMapVisible() const { return map_visible_; }
  int costCellCount() const { return cells_; }
  void clear();

 private:
  QCustomPlot* plot_;
  QCPColorMap* map_ = nullptr;
  QCPColorScale* scale_ = nullptr;
  QCPGraph* grid_ = nullptr;
  bool map_visible_ = false, grid_visible_ = false;
  int cells_ = 0;
};

}  // namespace mx::widgets
