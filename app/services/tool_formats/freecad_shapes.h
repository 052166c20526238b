#pragma once
// FreeCAD's tool-bit shapes (src/Mod/CAM/Tools/Shape/shape_aliases.json and the schemas of
// Path/Tool/shape/models/*.py): which are milling cutters, the MillExpert type of each, and the mapped
// parameters its schema holds. Drills, taps, reamers, probes and turning inserts are not milling cutters.
#include <QJsonObject>
#include <QString>
#include <optional>

namespace mx::app {

struct FreeCadMillShape {
  QString shape_type;                   // FreeCAD's shape name, written as "shape-type": "Endmill", "Bullnose", ...
  QString file;                         // the shape file a new bit names: "endmill.fcstd"
  QString type;                         // ToolSpec::type: "flat end mill", "bull nose end mill", ...
  bool has_cutting_edge_height = true;  // every milling shape but the slitting saw and the thread mill
  bool has_corner_radius = false;       // the bull nose only
};

// The shape of a bit: its "shape-type" when FreeCAD knows it, else the stem of its "shape" file
// ("v-bit.fcstd" -> VBit). A milling shape, or the reason the bit is not imported.
struct FreeCadShapeLookup {
  std::optional<FreeCadMillShape> mill;
  QString skip_reason;  // "a drill (drill.fcstd), not a milling cutter"
};
FreeCadShapeLookup freeCadShape(const QJsonObject& bit);

// The shape a new bit gets for a MillExpert type; the flat end mill for a type FreeCAD has no shape for
// (face mill, ...) or no type.
FreeCadMillShape freeCadShapeForType(const std::optional<QString>& type);

}  // namespace mx::app
