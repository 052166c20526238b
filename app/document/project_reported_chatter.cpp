#include "document/project_reported_chatter.h"

#include <QJsonArray>
#include <algorithm>

#include "document/project_rules.h"
#include "document/project_sections_io.h"

namespace mx::app {

namespace {

const QString kReports = "expert.reported_chatter";
const QStringList kReportKeys{"tool", "speed_rpm", "depth_mm", "freq_Hz"};
using chatter_report::kDepthMm;
using chatter_report::kFrequencyHz;
using chatter_report::kSpeedRpm;
constexpr FieldRange kIterations{0.0, 10000.0, "an integer in [0, 10000]", true};

ChatterReportSpec readReport(const ObjectReader& r) {
  ChatterReportSpec c;
  c.tool = r.string("tool");
  c.speed_rpm = r.number("speed_rpm", rules::kPositive);
  c.depth_mm = r.number("depth_mm", rules::kPositive);
  c.freq_Hz = r.optionalNumber("freq_Hz");
  QJsonObject unknown = r.object();
  for (const QString& key : kReportKeys) unknown.remove(key);
  c.unknown = unknown;
  return c;
}

QJsonObject reportJson(const ChatterReportSpec& c) {
  QJsonObject o = c.unknown;
  o.insert("tool", c.tool);
  o.insert("speed_rpm", c.speed_rpm);
  o.insert("depth_mm", c.depth_mm);
  if (c.freq_Hz) o.insert("freq_Hz", *c.freq_Hz);
  return o;
}

}  // namespace

void readReportedChatter(const ObjectReader& r, ExpertSpec& e) {
  if (r.has("max_malfunction_iterations")) {
    const double n = *r.optionalNumber("max_malfunction_iterations");
    checkField(r.pathOf("max_malfunction_iterations"), n, kIterations);
    e.max_malfunction_iterations = static_cast<int>(n);
  }
  const std::optional<QJsonArray> reports = r.optionalArray("reported_chatter");
  if (!reports) return;
  for (qsizetype i = 0; i < reports->size(); ++i)
    e.reported_chatter.push_back(readReport(elementObject(*reports, i, r.pathOf("reported_chatter"))));
}

void validateReportedChatter(const ExpertSpec& e, const std::vector<ToolSpec>& tools) {
  if (e.max_malfunction_iterations)
    checkField("expert.max_malfunction_iterations", *e.max_malfunction_iterations, kIterations);
  for (std::size_t i = 0; i < e.reported_chatter.size(); ++i) {
    const ChatterReportSpec& c = e.reported_chatter[i];
    const QString row = indexPath(kReports, static_cast<qsizetype>(i));
    const bool known = std::any_of(tools.begin(), tools.end(), [&](const ToolSpec& t) { return t.id == c.tool; });
    if (!known) throwBadField(row + ".tool", "'" + c.tool + "'", "the id of a tool of the project");
    checkField(row + ".speed_rpm", c.speed_rpm, kSpeedRpm);
    checkField(row + ".depth_mm", c.depth_mm, kDepthMm);
    checkField(row + ".freq_Hz", c.freq_Hz, kFrequencyHz);
  }
}

void putReportedChatter(QJsonObject& o, const ExpertSpec& e) {
  if (e.max_malfunction_iterations) {
    putNumber(o, "max_malfunction_iterations", *e.max_malfunction_iterations);
  } else {
    o.remove("max_malfunction_iterations");
  }
  if (e.reported_chatter.empty()) {
    o.remove("reported_chatter");
    return;
  }
  QJsonArray rows;
  for (const ChatterReportSpec& c : e.reported_chatter) rows.append(reportJson(c));
  o.insert("reported_chatter", rows);
}

}  // namespace mx::app
