#pragma once
// A plot's legend in a row of its own under the axis rect, `columns` entries wide: unlike the default
// inset legend it never hides a curve, a marker or a label of the plot.
class QCustomPlot;
class QCPLegend;

namespace mx::widgets {

void placeLegendUnderPlot(QCustomPlot* plot, int columns);

// The most columns, 1 to max_columns, in which the legend's entries (filled columns first) fit `width`
// pixels at their full size: no name is cut.
int legendColumnsFitting(const QCPLegend* legend, int width, int max_columns);

// The legend's width with all its entries in one column: the narrowest that cuts no name.
int legendWidthInOneColumn(const QCPLegend* legend);

// Re-flows the legend into legendColumnsFitting(...) columns; true when that changed its columns.
bool fitLegendColumns(QCPLegend* legend, int width, int max_columns);

}  // namespace mx::widgets
