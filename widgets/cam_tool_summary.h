#pragma once
// One line on what a tool's CAM library says about it (type, lengths, corner radius, cutting presets,
// source), shown under the tool library; the presets in full as a tooltip.
#include <QString>

#include "display_units.h"
#include "document/project.h"

namespace mx::widgets {

// "flat end mill · flute length 25.4 mm · overall 76.2 mm · stickout 38.1 mm · corner radius 0.5 mm ·
// 2 cutting presets · from Fusion 360"; "" for a tool without CAM data. Lengths in `units` (mm when null).
QString camToolSummary(const app::ToolSpec& tool, const DisplayUnits* units);
// One line per preset: "Aluminium roughing: 12000 rpm, 478.8 m/min, 0.08 mm/tooth, 2880 mm/min, ap 6 mm, ae 3 mm".
QString cuttingPresetsText(const app::ToolSpec& tool, const DisplayUnits* units);

}  // namespace mx::widgets
