#include "plot_legend.h"

#include <qcustomplot.h>

namespace mx::widgets {

void placeLegendUnderPlot(QCustomPlot* plot, int columns) {
  plot->axisRect()->insetLayout()->take(plot->legend);
  QCPLayoutGrid* layout = plot->plotLayout();
  layout->addElement(layout->rowCount(), 0, plot->legend);
  layout->setRowStretchFactor(layout->rowCount() - 1, 0.001);  // as tall as its entries, no more
  plot->legend->setFillOrder(QCPLegend::foColumnsFirst);
  plot->legend->setWrap(columns);
  plot->legend->setBorderPen(Qt::NoPen);
}

}  // namespace mx::widgets
