#pragma once
// Conversions between the supervisor (engine Grafcet charts and supervised runs, SI) and the supervisor
// view's display structs (Landers & Ulsoy face milling).
#include <QVector>
#include <vector>

#include "grafcet/grafcet_chart.h"
#include "grafcet_chart_data.h"
#include "supervision_data.h"
#include "supervisor/supervision_run.h"

namespace mx::gui {

widgets::GrafcetChartData chartData(const GrafcetChart& c);
GrafcetChart engineChart(const widgets::GrafcetChartData& d);
widgets::SupervisionSeries supervisionSeriesOf(const std::vector<SupervisionSample>& samples,
                                               const SupervisionScenario& s, double reference_n);
widgets::SupervisionMetricsView supervisionMetricsOf(const QString& controller, const SupervisionMetrics& m);
// Module activity records (the active letters whenever the set changes) as spans per letter.
QVector<widgets::ModuleSpan> moduleSpans(const std::vector<ModuleActivityRecord>& records, double end_s);
// The chart editor's issues: the engine's validation against the supervision signals.
QList<widgets::ChartIssue> chartIssues(const widgets::GrafcetChartData& d);

}  // namespace mx::gui
