#pragma once
// A plot's legend in a row of its own under the axis rect, `columns` entries wide: unlike the default
// inset legend it never hides a curve, a marker or a label of the plot.
class QCustomPlot;

namespace mx::widgets {

void placeLegendUnderPlot(QCustomPlot* plot, int columns);

}  // namespace mx::widgets
