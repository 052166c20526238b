#pragma once
// Grafcet charts in the project's JSON (format in docs/grafcet.md):
//   {"name": "SMC I",
//    "steps": [{"id": 1, "name": "Initialize Modules", "initial": true, "actions": ["L*"]}, ...],
//    "transitions": [{"id": 2, "from": [2], "to": [5], "receptivity": "a", "priority": 1}, ...]}
// The project parser reads supervisor.charts with it; every error is a ProjectError naming the JSON
// path, e.g. "supervisor.charts.smc1.transitions[3].receptivity: line 1, column 5: expected ')'".
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>
#include <optional>
#include <set>
#include <string>

#include "document/process_sections.h"
#include "grafcet/grafcet_chart.h"
#include "grafcet/grafcet_validation.h"

namespace mx::app {

// The chart's structure (types, required keys, id ranges) and the file's other keys; its content
// is checked by grafcetChartErrors.
GrafcetChartSpec grafcetChartFromJson(const QJsonValue& value, const QString& path);
// Back to JSON: the chart, its unknown keys, and the optional keys the file wrote at their default.
QJsonObject grafcetChartToJson(const GrafcetChartSpec& spec);
// `chart` (e.g. from the editor) with the keys of `previous` beyond the engine's struct: the chart's,
// and each step's / transition's matched by id, so that they follow their element on reorder.
GrafcetChartSpec grafcetChartSpecWith(const GrafcetChartSpec& previous, GrafcetChart chart);

// Where a validation issue lies in the JSON: "<path>.steps[2].name", "<path>.transitions[3].to",
// "<path>.steps" for chart-level issues.
QString grafcetIssuePath(const GrafcetIssue& issue, const QString& path);
// Every validation issue as "<json path>: <message>" (the signal check only with knownSignals).
QStringList grafcetChartErrors(const GrafcetChart& chart, const QString& path,
                               const std::optional<std::set<std::string>>& knownSignals = std::nullopt);
// Throws ProjectError with the first of grafcetChartErrors.
void checkGrafcetChart(const GrafcetChart& chart, const QString& path,
                       const std::optional<std::set<std::string>>& knownSignals = std::nullopt);

}  // namespace mx::app
