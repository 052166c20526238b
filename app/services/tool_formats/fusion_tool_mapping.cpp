// One Fusion tool record and ToolSpec: the id from post-process.number or the description, the
// geometry (geometry.DC, NOF, LCF, OAL, LB, RE and HA, in the tool's unit), the type and the presets.
// An export starts from the tool's origin record and rewrites only the values that changed, so that
// an unchanged tool is written back with the bytes it was read from.
#include <QJsonArray>
#include <QRegularExpression>
#include <QUuid>
#include <cmath>

#include "document/shortened_text.h"
#include "services/tool_formats/fusion_format.h"
#include "services/tool_formats/tool_library_io.h"

namespace mx::app::fusion {

namespace {

// The tool's fields in "geometry", with the tool-level expression Fusion may compute each one from.
struct GeometryField {
  NumberField number;
  const char* expression;  // nullptr: none known
};
const GeometryField kDiameter{{"DC", Quantity::Length, rules::kDiameterMm, false}, "tool_diameter"};
const GeometryField kFlutes{{"NOF", Quantity::Count, rules::kTeeth, false}, "tool_numberOfFlutes"};
const GeometryField kFluteLength{{"LCF", Quantity::Length, rules::kToolLengthMm, true}, "tool_fluteLength"};
const GeometryField kOverallLength{{"OAL", Quantity::Length, rules::kToolLengthMm, true}, "tool_overallLength"};
const GeometryField kBodyLength{{"LB", Quantity::Length, rules::kToolLengthMm, true}, "tool_bodyLength"};
const GeometryField kHelix{{"HA", Quantity::Angle, rules::kHelixDeg, false}, nullptr};
GeometryField cornerRadius(double diameter_mm) {
  return {{"RE", Quantity::Length, rules::cornerRadius(diameter_mm), false}, "tool_cornerRadius"};
}

constexpr double kMaxToolNumber = 1e9;
const QUuid kRecordNamespace{"835e8632-a40c-4981-b78d-6ab32fe633c8"};  // MillExpert's, for new records' guids
const QString kGeometryKey = QStringLiteral("geometry");
const QString kExpressionsKey = QStringLiteral("expressions");
const QString kPostProcessKey = QStringLiteral("post-process");

QString geometryPath(const GeometryField& field) {
  return QString("geometry.%1").arg(field.number.key);
}

std::optional<int> toolNumber(const QJsonValue& number) {
  if (!number.isDouble()) return std::nullopt;
  const double n = number.toDouble();
  if (!(n >= 0.0 && n <= kMaxToolNumber) || n != std::floor(n)) return std::nullopt;
  return static_cast<int>(n);
}

std::optional<QString> idCandidate(const QJsonObject& tool) {
  const std::optional<int> number = toolNumber(tool.value(kPostProcessKey).toObject().value("number"));
  if (number && *number > 0) return QString("T%1").arg(*number);
  for (const char* key : {"description", "guid"}) {
    const QString text = tool.value(key).toString().trimmed();
    if (!text.isEmpty()) return text;
  }
  return std::nullopt;
}

double requiredNumber(const QJsonObject& geometry, const GeometryField& field, Unit unit, const Place& place) {
  const std::optional<double> value = readNumber(geometry, field.number, unit, place, geometryPath(field));
  if (!value)
    fail(place, geometryPath(field),
         QString("missing (required %1%2)")
             .arg(field.number.rule.requirement(), field.number.quantity == Quantity::Length ? " mm" : ""));
  return *value;
}

void checkWithinOverallLength(const QJsonObject& geometry, const GeometryField& field,
                              const std::optional<double>& length, const std::optional<double>& overall,
                              const Place& place) {
  if (!length || !overall || *length <= *overall) return;
  fail(place, geometryPath(field),
       QString("%1 must be <= geometry.OAL (%2)")
           .arg(quoted(formatValue(geometry.value(field.number.key))), quoted(formatValue(geometry.value("OAL")))));
}

void dropExpression(QJsonObject& record, const char* name) {
  if (name == nullptr) return;
  QJsonObject expressions = record.value(kExpressionsKey).toObject();
  if (!expressions.contains(name)) return;
  expressions.remove(name);
  record.insert(kExpressionsKey, expressions);
}

// Writes `value` into the record's geometry; a changed value also drops Fusion's expression for it,
// which Fusion would otherwise evaluate over the new value.
void putGeometry(QJsonObject& record, QJsonObject& geometry, const GeometryField& field,
                 const std::optional<double>& value, Unit unit) {
  const QJsonValue origin = geometry.value(field.number.key);
  if (value) {
    const QJsonValue written = numberToWrite(origin, *value, field.number, unit);
    geometry.insert(field.number.key, written);
    if (written != origin) dropExpression(record, field.expression);
    return;
  }
  const bool origin_mapped = origin.isDouble() && !(field.number.zero_is_unset && origin.toDouble() == 0.0);
  if (!origin_mapped) return;
  geometry.remove(field.number.key);  // the value was removed in MillExpert
  dropExpression(record, field.expression);
}

void putId(QJsonObject& record, const QString& id) {
  if (idCandidate(record) == id) return;
  static const QRegularExpression tool_number("^T([1-9][0-9]{0,8})$");
  const QRegularExpressionMatch match = tool_number.match(id);
  if (match.hasMatch()) {
    QJsonObject post_process = record.value(kPostProcessKey).toObject();
    post_process.insert("number", match.captured(1).toInt());
    record.insert(kPostProcessKey, post_process);
    if (record.value("description").toString().trimmed().isEmpty()) record.insert("description", id);
  } else {
    record.insert("description", id);
  }
}

Unit recordUnit(const QJsonObject& record, const QString& id) {
  try {
    return toolUnit(record, std::nullopt, {QStringLiteral("origin"), id});
  } catch (const ToolLibraryError& e) {
    throw ToolLibraryError(QString("Fusion export of tool %1: its Fusion origin record has no usable unit (%2)")
                               .arg(quoted(id), QString::fromStdString(e.what())));
  }
}

void putPresets(QJsonObject& record, const std::vector<CuttingPresetSpec>& presets, Unit unit) {
  QJsonObject start = record.value("start-values").toObject();
  if (presets.empty() && !start.contains("presets")) return;
  start.insert("presets", presetsToWrite(presets, start.value("presets").toArray(), unit));
  record.insert("start-values", start);
}

}  // namespace

std::optional<QString> toolId(const QJsonObject& tool, const Place& place) {
  const QJsonValue post_process = tool.value(kPostProcessKey);
  if (!post_process.isUndefined() && !post_process.isNull() && !post_process.isObject())
    fail(place, kPostProcessKey, "must be an object");
  const QJsonValue number = post_process.toObject().value("number");
  if (!number.isUndefined() && !number.isNull() && !toolNumber(number))
    fail(place, "post-process.number",
         QString("%1 must be an integer in [0, %2]")
             .arg(quoted(formatValue(number)))
             .arg(static_cast<qint64>(kMaxToolNumber)));
  return idCandidate(tool);
}

QString toolLabel(const QJsonObject& tool, qsizetype position) {
  return idCandidate(tool).value_or(QString("#%1").arg(position + 1));
}

ToolSpec readMillingTool(const QJsonObject& tool, const QString& id, Unit unit, const Place& place) {
  const QJsonValue geometry_value = tool.value(kGeometryKey);
  if (!geometry_value.isObject())
    fail(place, kGeometryKey, "missing or not an object (a milling cutter needs geometry.DC and geometry.NOF)");
  const QJsonObject geometry = geometry_value.toObject();
  ToolSpec spec;
  spec.id = id;
  spec.type = tool.value("type").toString();
  spec.diameter_mm = requiredNumber(geometry, kDiameter, unit, place);
  spec.teeth = static_cast<int>(requiredNumber(geometry, kFlutes, unit, place));
  spec.flute_length_mm = readNumber(geometry, kFluteLength.number, unit, place, geometryPath(kFluteLength));
  spec.overall_length_mm = readNumber(geometry, kOverallLength.number, unit, place, geometryPath(kOverallLength));
  spec.stickout_mm = readNumber(geometry, kBodyLength.number, unit, place, geometryPath(kBodyLength));
  checkWithinOverallLength(geometry, kFluteLength, spec.flute_length_mm, spec.overall_length_mm, place);
  checkWithinOverallLength(geometry, kBodyLength, spec.stickout_mm, spec.overall_length_mm, place);
  const GeometryField corner = cornerRadius(spec.diameter_mm);
  spec.corner_radius_mm = readNumber(geometry, corner.number, unit, place, geometryPath(corner));
  spec.helix_deg = readNumber(geometry, kHelix.number, unit, place, geometryPath(kHelix)).value_or(0.0);
  spec.cutting_data = readPresets(tool, unit, place);
  return spec;
}

QJsonObject toolToWrite(const ToolSpec& tool) {
  const bool from_fusion = tool.origin && tool.origin->format == "fusion";
  QJsonObject record = from_fusion ? tool.origin->data : QJsonObject{};
  const Unit unit = from_fusion ? recordUnit(record, tool.id) : Unit::Millimeters;
  if (!from_fusion) {
    record.insert("unit", unitName(unit));
    record.insert("guid", QUuid::createUuidV5(kRecordNamespace, tool.id).toString(QUuid::WithoutBraces));
  }
  if (tool.type) {
    record.insert("type", *tool.type);
  } else if (!record.value("type").isString()) {
    record.insert("type", "flat end mill");  // MillExpert's default cutter
  }
  putId(record, tool.id);
  QJsonObject geometry = record.value(kGeometryKey).toObject();
  putGeometry(record, geometry, kDiameter, tool.diameter_mm, unit);
  putGeometry(record, geometry, kFlutes, tool.teeth, unit);
  putGeometry(record, geometry, kFluteLength, tool.flute_length_mm, unit);
  putGeometry(record, geometry, kOverallLength, tool.overall_length_mm, unit);
  putGeometry(record, geometry, kBodyLength, tool.stickout_mm, unit);
  putGeometry(record, geometry, cornerRadius(tool.diameter_mm), tool.corner_radius_mm, unit);
  if (tool.helix_deg != 0.0 || geometry.contains(kHelix.number.key))
    putGeometry(record, geometry, kHelix, tool.helix_deg, unit);
  record.insert(kGeometryKey, geometry);
  putPresets(record, tool.cutting_data, unit);
  return record;
}

}  // namespace mx::app::fusion
