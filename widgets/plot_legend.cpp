#include "plot_legend.h"

#include <qcustomplot.h>

#include <QVector>
#include <algorithm>

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

namespace {
// The entries' widths in their order: a re-flowed grid has empty cells after the last entry.
QVector<int> entryWidths(const QCPLegend* legend) {
  QVector<int> widths;
  for (int i = 0; i < legend->itemCount(); ++i)
    if (const QCPAbstractLegendItem* item = legend->item(i)) widths.push_back(item->minimumOuterSizeHint().width());
  return widths;
}

// The legend's width in `columns` columns: entry i in column i % columns, each column as wide as its
// widest entry.
int widthInColumns(const QCPLegend* legend, const QVector<int>& entries, int columns) {
  QVector<int> widths(columns, 0);
  for (int i = 0; i < entries.size(); ++i) widths[i % columns] = std::max(widths[i % columns], entries[i]);
  int width = legend->margins().left() + legend->margins().right() + (columns - 1) * legend->columnSpacing();
  for (int w : widths) width += w;
  return width;
}
}  // namespace

int legendColumnsFitting(const QCPLegend* legend, int width, int max_columns) {
  const QVector<int> entries = entryWidths(legend);
  int columns = std::max(1, std::min(max_columns, static_cast<int>(entries.size())));
  while (columns > 1 && widthInColumns(legend, entries, columns) > width) --columns;
  return columns;
}

int legendWidthInOneColumn(const QCPLegend* legend) {
  return widthInColumns(legend, entryWidths(legend), 1);
}

bool fitLegendColumns(QCPLegend* legend, int width, int max_columns) {
  const int columns = legendColumnsFitting(legend, width, max_columns);
  if (legend->wrap() == columns && legend->columnCount() <= columns) return false;
  legend->setWrap(columns);
  legend->setFillOrder(QCPLegend::foColumnsFirst, true);  // re-flows the entries into the columns
  return true;
}

}  // namespace mx::widgets
