#include "document/tool_geometry.h"

#include <QStringList>
#include <cmath>
#include <numbers>

namespace mx::app {

namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
constexpr double kMPerMm = 1e-3;
constexpr double kMPerUm = 1e-6;

QString lengthRule(std::size_t got, int teeth) {
  return QString("must have one value per tooth (teeth = %1), got %2").arg(teeth).arg(got);
}

// The first value `rule` refuses, or an ok issue.
ToothListIssue firstRefused(const std::vector<double>& values, const NumberRule& rule, const QString& why = {}) {
  for (std::size_t j = 0; j < values.size(); ++j) {
    if (!rule.accepts(values[j])) return {static_cast<int>(j), rule.mustBe(values[j]) + why};
  }
  return {};
}

std::vector<double> scaled(const std::optional<std::vector<double>>& values, double factor) {
  std::vector<double> out;
  if (values)
    for (double v : *values) out.push_back(v * factor);
  return out;
}

}  // namespace

ToothListIssue pitchIssue(const std::vector<double>& pitch_deg, int teeth) {
  if (pitch_deg.size() != static_cast<std::size_t>(teeth)) return {-1, lengthRule(pitch_deg.size(), teeth)};
  if (ToothListIssue issue = firstRefused(pitch_deg, rules::kPitchDeg); !issue.ok()) return issue;
  double sum = 0.0;
  for (double p : pitch_deg) sum += p;
  if (!(std::abs(sum - 360.0) <= kPitchSumToleranceDeg))
    return {-1, QString("must sum to 360 within %1, sums to %2")
                    .arg(formatNumber(kPitchSumToleranceDeg), QString::number(sum, 'g', 12))};
  return {};
}

ToothListIssue runoutIssue(const std::vector<double>& runout_um, int teeth, double diameter_mm) {
  if (runout_um.size() != static_cast<std::size_t>(teeth)) return {-1, lengthRule(runout_um.size(), teeth)};
  return firstRefused(
      runout_um, rules::runoutUm(diameter_mm),
      QString(" (|runout| < D/4 = 250 * diameter_mm, diameter_mm = %1)").arg(formatNumber(diameter_mm)));
}

QString formatNumberList(const std::vector<double>& values) {
  QStringList items;
  for (double v : values) items << formatNumber(v);
  return "[" + items.join(", ") + "]";
}

void validateToolGeometry(const QString& toolPath, const ToolSpec& tool) {
  const auto check = [&](const char* key, const std::vector<double>& values, const ToothListIssue& issue) {
    if (issue.ok()) return;
    const QString path = childPath(toolPath, key);
    if (issue.index < 0) throw ProjectError(QString("%1 = %2: %3").arg(path, formatNumberList(values), issue.rule));
    throw ProjectError(
        QString("%1 = %2: %3")
            .arg(indexPath(path, issue.index), formatNumber(values[std::size_t(issue.index)]), issue.rule));
  };
  if (tool.pitch_deg) check("pitch_deg", *tool.pitch_deg, pitchIssue(*tool.pitch_deg, tool.teeth));
  if (tool.runout_um) check("runout_um", *tool.runout_um, runoutIssue(*tool.runout_um, tool.teeth, tool.diameter_mm));
}

MillingSetup cutterGeometryOf(const ToolSpec& tool) {
  MillingSetup s;
  s.tool_id = tool.id.toStdString();
  s.teeth = tool.teeth;
  s.diameter_m = tool.diameter_mm * kMPerMm;
  s.helix_rad = tool.helix_deg * kRadPerDeg;
  s.pitch_rad = scaled(tool.pitch_deg, kRadPerDeg);
  s.runout_m = scaled(tool.runout_um, kMPerUm);
  return s;
}

}  // namespace mx::app
