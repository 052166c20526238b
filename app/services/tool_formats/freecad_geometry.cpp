#include "services/tool_formats/freecad_geometry.h"

#include "document/project_rules.h"
#include "document/shortened_text.h"
#include "services/tool_formats/freecad_quantity.h"

namespace mx::app {

namespace {

QString echoed(const QJsonValue& value) {
  return value.isString() ? quoted(value.toString()) : formatValue(value);
}

// The parameter as a length in mm; 0 is absent unless `zero_is_value`.
FreeCadField lengthField(const QJsonObject& parameters, const QString& name, const NumberRule& rule,
                         bool zero_is_value = false) {
  FreeCadField field{name, std::nullopt, {}};
  if (!parameters.contains(name)) return field;
  const QJsonValue raw = parameters.value(name);
  const LengthParse parsed = parseFreeCadLength(raw);
  if (!parsed.mm) {
    field.problem = parsed.problem;
  } else if (*parsed.mm == 0.0 && !zero_is_value) {
    return field;
  } else if (!rule.accepts(*parsed.mm)) {
    field.problem = QString("%1 (%2 mm): %3").arg(echoed(raw), formatNumber(*parsed.mm), rule.mustBe(*parsed.mm));
  } else {
    field.value = parsed.mm;
  }
  return field;
}

// FreeCAD writes the count as an integer (App::PropertyInteger); a string of digits is read too.
FreeCadField flutesField(const QJsonObject& parameters) {
  FreeCadField field{"Flutes", std::nullopt, {}};
  if (!parameters.contains(field.parameter)) return field;
  const QJsonValue raw = parameters.value(field.parameter);
  bool ok = raw.isDouble();
  double count = raw.toDouble();
  if (raw.isString()) count = raw.toString().trimmed().toDouble(&ok);
  if (ok && count == 0.0) return field;
  if (!ok || !rules::kTeeth.accepts(count)) {
    field.problem = QString("%1: %2").arg(echoed(raw), rules::kTeeth.mustBe(count));
    return field;
  }
  field.value = count;
  return field;
}

FreeCadField cornerRadiusField(const QJsonObject& parameters, const FreeCadField& diameter) {
  const double d = diameter.value.value_or(1000.0);
  const NumberRule rule = rules::cornerRadius(d);
  for (const char* name : {"CornerRadius", "TorusRadius"})
    if (parameters.contains(name)) return lengthField(parameters, name, rule, true);
  FreeCadField flat = lengthField(parameters, "FlatRadius", rules::kNonNegative, true);
  if (!flat.value || !diameter.value) return flat;
  // Older bull noses give the flat bottom's radius; FreeCAD migrates it to D/2 - FlatRadius.
  const double corner = d / 2.0 - *flat.value;
  if (!rule.accepts(corner)) {
    flat.problem = QString("%1: gives a corner radius of %2 mm (Diameter/2 - FlatRadius), which %3")
                       .arg(echoed(parameters.value(flat.parameter)), formatNumber(corner), rule.mustBe(corner));
    flat.value.reset();
    return flat;
  }
  flat.value = corner;
  return flat;
}

// The cutting edge cannot be longer than the tool.
void checkAgainstLength(FreeCadField& cutting_edge, const FreeCadField& length) {
  if (!cutting_edge.value || !length.value || *cutting_edge.value <= *length.value) return;
  cutting_edge.problem =
      QString("%1 mm: must be <= %2 mm (Length)").arg(formatNumber(*cutting_edge.value), formatNumber(*length.value));
  cutting_edge.value.reset();
}

}  // namespace

FreeCadGeometry readFreeCadGeometry(const QJsonObject& parameters, const FreeCadMillShape& shape) {
  FreeCadGeometry g;
  g.diameter = lengthField(parameters, "Diameter", rules::kDiameterMm, true);
  if (!g.diameter.value && g.diameter.problem.isEmpty())
    g.diameter.problem = "missing: a milling bit needs its diameter (\"6.00 mm\")";
  g.flutes = flutesField(parameters);
  g.length = lengthField(parameters, "Length", rules::kToolLengthMm);
  g.cutting_edge_height = {"CuttingEdgeHeight", std::nullopt, {}};
  if (shape.has_cutting_edge_height) {
    g.cutting_edge_height = lengthField(parameters, "CuttingEdgeHeight", rules::kToolLengthMm);
    checkAgainstLength(g.cutting_edge_height, g.length);
  }
  g.corner_radius = {"CornerRadius", std::nullopt, {}};
  if (shape.has_corner_radius) g.corner_radius = cornerRadiusField(parameters, g.diameter);
  return g;
}

}  // namespace mx::app
