#include "services/reported_chatter.h"

#include <cmath>

#include "document/project_rules.h"
#include "document/shortened_text.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {

// The same ranges as expert.reported_chatter[] in the project file.
double numberIn(const QString& text, const QString& whole, const char* what, const FieldRange& range) {
  bool ok = false;
  const double v = text.trimmed().toDouble(&ok);
  if (!ok || !std::isfinite(v) || v < range.lo || v > range.hi)
    throw InputError(
        QString("--chatter-at = %1: %2 %3 must be a number %4").arg(quoted(whole), what, quoted(text), range.text));
  return v;
}

QString pointText(const ExpertPoint& q) {
  return QString("(%1 rpm, %2 mm, %3 mm/tooth)")
      .arg(revPerSToRpm(q.speed_rev_per_s), 0, 'f', 0)
      .arg(q.depth_m * 1e3, 0, 'f', 4)
      .arg(q.feed_per_tooth_m * 1e3, 0, 'f', 3);
}

}  // namespace

ChatterReportSpec parseChatterAt(const QString& text, const QString& tool) {
  const QStringList parts = text.split(':');
  if (parts.size() < 2 || parts.size() > 3)
    throw InputError(
        QString("--chatter-at = %1: must be SPEED_RPM:DEPTH_MM or SPEED_RPM:DEPTH_MM:FREQ_HZ").arg(quoted(text)));
  ChatterReportSpec c;
  c.tool = tool;
  c.speed_rpm = numberIn(parts[0], text, "speed [rpm]", chatter_report::kSpeedRpm);
  c.depth_mm = numberIn(parts[1], text, "depth [mm]", chatter_report::kDepthMm);
  if (parts.size() == 3) c.freq_Hz = numberIn(parts[2], text, "frequency [Hz]", chatter_report::kFrequencyHz);
  return c;
}

std::vector<ChatterReport> engineChatterReports(const std::vector<ChatterReportSpec>& reports,
                                                const QStringList& tool_ids) {
  std::vector<ChatterReport> out;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const ChatterReportSpec& c = reports[i];
    const qsizetype tool = tool_ids.indexOf(c.tool);
    if (tool < 0)
      throw ProjectError(QString("expert.reported_chatter[%1].tool = %2: must be the id of a tool of the project")
                             .arg(i)
                             .arg(quoted(c.tool)));
    ChatterReport r;
    r.tool = static_cast<std::size_t>(tool);
    r.speed_rev_per_s = rpmToRevPerS(c.speed_rpm);
    r.depth_m = c.depth_mm * 1e-3;
    r.frequency_hz = c.freq_Hz;
    out.push_back(r);
  }
  return out;
}

QJsonObject reportedChatterJson(const ChatterReportSpec& c, const ExpertResult& result, const QStringList& tool_ids) {
  const ChatterReport r = engineChatterReports({c}, tool_ids).front();
  const ChatterRegion region = chatterRegionOf(r);
  const bool holds = !result.ranking.tools.empty() && reportHolds(r, result.chosenTool(), result.chosenPoint());
  return {{"tool", c.tool},
          {"speed_rpm", c.speed_rpm},
          {"depth_mm", c.depth_mm},
          {"freq_Hz", c.freq_Hz ? QJsonValue(*c.freq_Hz) : QJsonValue()},
          {"region", QJsonObject{{"speed_from_rpm", revPerSToRpm(region.speed_from_rev_per_s)},
                                 {"speed_to_rpm", revPerSToRpm(region.speed_to_rev_per_s)},
                                 {"depth_from_mm", region.depth_from_m * 1e3}}},
          {"holds_chosen_point", holds}};
}

QString unresolvedChatterMessage(const ExpertResult& result, const std::vector<ChatterReportSpec>& reports,
                                 const QStringList& tool_ids, int bound) {
  if (!result.malfunction_limit_reached || !result.unresolved_report) return {};
  if (*result.unresolved_report >= reports.size())
    return QString("Rule 6 stopped at its bound of %1 iterations with the chosen point in reported chatter").arg(bound);
  const ChatterReportSpec& c = reports.at(*result.unresolved_report);
  const auto& w = result.weights.c;
  return QString(
             "Rule 6 stopped at its bound of %1 iterations (expert.max_malfunction_iterations): the chosen point %2 "
             "of tool %3 still lies in the chatter reported at %4 rpm, %5 mm (+-2 % in speed, that depth and "
             "deeper); final c = (%6, %7, %8). Report a deeper threshold, raise the bound, or choose another tool")
      .arg(bound)
      .arg(pointText(result.chosenPoint()), tool_ids.value(static_cast<qsizetype>(result.chosenTool())))
      .arg(c.speed_rpm, 0, 'g', 6)
      .arg(c.depth_mm, 0, 'g', 6)
      .arg(w[0], 0, 'f', 4)
      .arg(w[1], 0, 'f', 4)
      .arg(w[2], 0, 'f', 4);
}

}  // namespace mx::app
