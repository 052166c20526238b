#pragma once
// The geometry MillExpert maps from a FreeCAD bit's "parameter" object, for the reader (which refuses a
// bad value) and the writer (which keeps a parameter whose value is still the tool's). Each field is a
// value, absent, or a problem naming the parameter. FreeCAD writes 0 for a length or a flute count it
// was never given (get_unset_value_for), so 0 reads as absent; a 0 diameter is refused, and a 0 corner
// radius is a sharp corner.
#include <QJsonObject>
#include <QString>
#include <optional>

#include "services/tool_formats/freecad_shapes.h"

namespace mx::app {

struct FreeCadField {
  QString parameter;  // the parameter read: "Diameter", "FlatRadius", ...
  std::optional<double> value;
  QString problem;  // empty when the value is usable (or absent)
};

struct FreeCadGeometry {
  FreeCadField diameter;             // Diameter, mm
  FreeCadField flutes;               // Flutes, a count
  FreeCadField cutting_edge_height;  // CuttingEdgeHeight, mm (shapes that have one)
  FreeCadField length;               // Length (overall), mm
  FreeCadField corner_radius;        // CornerRadius, else TorusRadius, else Diameter/2 - FlatRadius (bull nose)
};

FreeCadGeometry readFreeCadGeometry(const QJsonObject& parameters, const FreeCadMillShape& shape);

}  // namespace mx::app
