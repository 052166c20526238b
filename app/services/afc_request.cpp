#include "services/afc_request.h"

#include <QRegularExpression>

#include "core/invalid_input.h"
#include "document/project_rules.h"
#include "model/cutting_force.h"
#include "services/service_errors.h"

namespace mx::app {
namespace {

// "TOOL CALL 5 Z S2000": the number after CALL of the first TOOL CALL; 0 when there is none or it
// calls the tool by name.
int firstToolCallNumber(const GcodeProgram& program) {
  static const QRegularExpression kCall(R"(CALL\s+(\d+)(\s|$))");
  for (const GcodeBlock& b : program.blocks) {
    if (b.keyword != "TOOL CALL") continue;
    const QRegularExpressionMatch m = kCall.match(QString::fromStdString(b.text).toUpper());
    return m.hasMatch() ? m.captured(1).toInt() : 0;
  }
  return 0;
}

}  // namespace

QString afcNameFor(const QString& tool_id) {
  QString name = "MX_";
  for (const QChar c : tool_id.toUpper())
    if ((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_') name += c;
  return name.left(static_cast<int>(kAfcNameLength));
}

AfcOutcome afcFromProject(const Project& project, const GcodeProgram& program, std::optional<double> speed_rpm,
                          char ovld) {
  if (program.dialect.dialect != GcodeDialect::Heidenhain)
    throw InputError(QString("--afc: Heidenhain AFC needs a Heidenhain program; this one is %1")
                         .arg(QString::fromStdString(std::string(dialectTitle(program.dialect.dialect)))));
  if (!project.operating_point)
    throwMissingField("operating_point",
                      "the chosen point {tool, speed_rpm, depth_mm, feed_mm_per_tooth}, which AFC is "
                      "taught at");
  AfcOutcome out;
  out.point = *project.operating_point;
  if (speed_rpm) out.point.speed_rpm = *speed_rpm;
  out.tool = out.point.tool;
  const MillingSetup setup = project.setupFor(out.tool);
  const double n = out.point.speed_rpm / 60.0;
  const CutPerformance perf = evaluateCut(setup, {n, out.point.depth_mm * 1e-3, out.point.feed_mm_per_tooth * 1e-3});
  AfcPrediction p;
  p.mean_power_W = perf.mean_power_w;
  p.peak_power_W = perf.peak_power_w;
  const double available = availablePowerW(project.machine, out.point.speed_rpm);
  p.available_power_W = std::isfinite(available) ? available : 0.0;
  p.feed_per_tooth_m = out.point.feed_mm_per_tooth * 1e-3;
  p.max_feed_per_tooth_m = project.operation ? project.operation->max_feed_per_tooth_mm * 1e-3 : 0.0;
  try {
    out.teach_in = afcFromPrediction(p, afcNameFor(out.tool).toStdString(), ovld);
  } catch (const InvalidInput& e) {
    throw InputError(QString::fromStdString(e.what()));
  }
  out.tool_number = firstToolCallNumber(program);
  if (out.tool_number == 0)
    for (std::size_t i = 0; i < project.tools.size(); ++i)
      if (project.tools[i].id == out.tool) out.tool_number = static_cast<int>(i) + 1;
  return out;
}

}  // namespace mx::app
