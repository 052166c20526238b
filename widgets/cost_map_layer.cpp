#include "cost_map_layer.h"

#include <qcustomplot.h>

#include <cmath>

namespace mx::widgets {

CostMapLayer::CostMapLayer(QCustomPlot* plot) : plot_(plot) {}

void CostMapLayer::clear() {
  if (map_) plot_->removePlottable(map_);
  if (scale_) {
    plot_->plotLayout()->remove(scale_);
    plot_->plotLayout()->simplify();
  }
  map_ = nullptr;
  scale_ = nullptr;
  grid_ = nullptr;  // graphs are cleared with the chart
  cells_ = 0;
}

void CostMapLayer::setCostMap(const QVector<double>& speeds, const QVector<double>& depths,
                              const QVector<double>& cost) {
  if (map_) plot_->removePlottable(map_);
  map_ = nullptr;
  cells_ = 0;
  if (speeds.size() < 2 || depths.size() < 2 || cost.size() != speeds.size() * depths.size()) return;
  map_ = new QCPColorMap(plot_->xAxis, plot_->yAxis);
  map_->setName(QObject::tr("tool cost C (eq. 13)"));
  map_->data()->setSize(static_cast<int>(speeds.size()), static_cast<int>(depths.size()));
  map_->data()->setRange(QCPRange(speeds.front(), speeds.back()), QCPRange(depths.front(), depths.back()));
  double lo = 1e300, hi = -1e300;
  for (qsizetype i = 0; i < speeds.size(); ++i)
    for (qsizetype j = 0; j < depths.size(); ++j) {
      const double c = cost[i * depths.size() + j];
      map_->data()->setCell(static_cast<int>(i), static_cast<int>(j), c);
      if (std::isfinite(c)) {
        map_->data()->setAlpha(static_cast<int>(i), static_cast<int>(j), 170);
        lo = std::min(lo, c), hi = std::max(hi, c);
        ++cells_;
      } else {
        map_->data()->setAlpha(static_cast<int>(i), static_cast<int>(j), 0);
      }
    }
  if (!scale_) {
    scale_ = new QCPColorScale(plot_);
    plot_->plotLayout()->addElement(0, 1, scale_);
    scale_->setType(QCPAxis::atRight);
    scale_->axis()->setLabel(QObject::tr("tool cost C [-] (lower is better)"));
  }
  map_->setColorScale(scale_);
  QCPColorGradient gradient(QCPColorGradient::gpJet);
  gradient.setNanHandling(QCPColorGradient::nhTransparent);
  map_->setGradient(gradient);
  if (lo < hi) map_->setDataRange(QCPRange(lo, std::min(hi, lo * 4.0)));
  map_->setInterpolate(false);
  map_->removeFromLegend();
  map_->setLayer("grid");  // under the lobes, the regions' outlines and the markers
  setCostMapVisible(map_visible_);
}

void CostMapLayer::setGridPoints(const QVector<double>& speeds, const QVector<double>& depths) {
  if (!grid_) {
    grid_ = plot_->addGraph();
    grid_->setName(QObject::tr("admissible grid points"));
    grid_->setLineStyle(QCPGraph::lsNone);
    grid_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDot, QColor(20, 90, 20), 3));
  }
  grid_->setData(speeds, depths);
  setGridVisible(grid_visible_);
}

void CostMapLayer::setCostMapVisible(bool visible) {
  map_visible_ = visible;
  if (map_) map_->setVisible(visible);
  if (scale_) scale_->setVisible(visible && map_);
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void CostMapLayer::setGridVisible(bool visible) {
  grid_visible_ = visible;
  if (grid_) {
    grid_->setVisible(visible);
    if (visible)
      grid_->addToLegend();
    else
      grid_->removeFromLegend();
  }
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

}  // namespace mx::widgets
