#pragma once
// Grafcet charts in JSON (issue 8; format in docs/grafcet.md):
//   {"name": "SMC I",
//    "steps": [{"id": 1, "name": "Initialize Modules", "initial": true, "actions": ["L*"]}, ...],
//    "transitions": [{"id": 2, "from": [2], "to": [5], "receptivity": "a", "priority": 1}, ...]}
// Every error is a ProjectError naming the JSON path, e.g.
//   "supervisor.charts.smc1.transitions[3].receptivity: line 1, column 5: expected ')'".
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>
#include <optional>
#include <set>
#include <string>

#include "supervisor/grafcet_chart.h"
#include "supervisor/grafcet_validation.h"

namespace mx::app {

// The chart's structure (types, required keys, ranges); no validation of its content.
GrafcetChart grafcetChartFromJson(const QJsonValue& value, const QString& path);

// Where a validation issue lies in the JSON: "<path>.steps[2].name", "<path>.transitions[3].to",
// "<path>.steps" for chart-level issues.
QString grafcetIssuePath(const GrafcetIssue& issue, const QString& path);
// Every validation issue as "<json path>: <message>" (the signal check only with knownSignals).
QStringList grafcetChartErrors(const GrafcetChart& chart, const QString& path,
                               const std::optional<std::set<std::string>>& knownSignals = std::nullopt);

// Reads and validates; throws ProjectError with the first error.
GrafcetChart loadGrafcetChart(const QJsonValue& value, const QString& path,
                              const std::optional<std::set<std::string>>& knownSignals = std::nullopt);

// Back to JSON. Keys this format does not know (e.g. an editor's layout) are kept from `previous`
// (the chart object it was read from), at the chart level and per step / transition id.
QJsonObject grafcetChartToJson(const GrafcetChart& chart, const QJsonObject& previous = {});

}  // namespace mx::app
