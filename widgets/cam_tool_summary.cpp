#include "cam_tool_summary.h"

#include <QObject>
#include <QStringList>

#include "count_text.h"

namespace mx::widgets {

namespace {

QString length(double mm, const DisplayUnits* units) {
  if (!units) return QString("%1 mm").arg(QString::number(mm, 'g', 6));
  return QString("%1 %2").arg(QString::number(units->fromMm(mm), 'g', 6), units->lengthSuffix());
}

void addLength(QStringList& parts, const QString& label, const std::optional<double>& mm, const DisplayUnits* units) {
  if (mm) parts << QString("%1 %2").arg(label, length(*mm, units));
}

QString sourceName(const QString& format) {
  if (format == "fusion") return QStringLiteral("Fusion 360");
  if (format == "freecad") return QStringLiteral("FreeCAD");
  if (format == "linuxcnc") return QStringLiteral("LinuxCNC");
  return format;
}

QString presetText(const app::CuttingPresetSpec& p, const DisplayUnits* units) {
  QStringList values;
  const auto number = [](double v) { return QString::number(v, 'g', 6); };
  if (p.speed_rpm) values << QString("%1 rpm").arg(number(*p.speed_rpm));
  if (p.surface_speed_m_min) values << QString("%1 m/min").arg(number(*p.surface_speed_m_min));
  if (p.feed_per_tooth_mm) values << QString("%1 mm/tooth").arg(number(*p.feed_per_tooth_mm));
  if (p.feed_mm_min) values << QString("%1 mm/min").arg(number(*p.feed_mm_min));
  if (p.axial_depth_mm) values << QString("ap %1").arg(length(*p.axial_depth_mm, units));
  if (p.radial_depth_mm) values << QString("ae %1").arg(length(*p.radial_depth_mm, units));
  return values.isEmpty() ? p.name : QString("%1: %2").arg(p.name, values.join(", "));
}

}  // namespace

QString camToolSummary(const app::ToolSpec& tool, const DisplayUnits* units) {
  QStringList parts;
  if (tool.type) parts << *tool.type;
  addLength(parts, QObject::tr("flute length"), tool.flute_length_mm, units);
  addLength(parts, QObject::tr("overall"), tool.overall_length_mm, units);
  addLength(parts, QObject::tr("stickout"), tool.stickout_mm, units);
  addLength(parts, QObject::tr("corner radius"), tool.corner_radius_mm, units);
  if (!tool.cutting_data.empty())
    parts << countText(qsizetype(tool.cutting_data.size()), "cutting preset", "cutting presets");
  if (tool.origin) parts << QObject::tr("from %1").arg(sourceName(tool.origin->format));
  return parts.join(QStringLiteral(" · "));
}

QString cuttingPresetsText(const app::ToolSpec& tool, const DisplayUnits* units) {
  QStringList lines;
  for (const app::CuttingPresetSpec& p : tool.cutting_data) lines << presetText(p, units);
  return lines.join('\n');
}

}  // namespace mx::widgets
