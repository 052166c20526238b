// A Fusion tool's cutting presets (start-values.presets[]: name, n, v_c, f_z, v_f, stepdown, stepover,
// with Fusion's feeds for ramp, plunge, lead-in and lead-out, coolant, guid ...) and
// CuttingPresetSpec. The keys MillExpert does not map stay in the preset's unknown keys.
#include <QJsonArray>
#include <array>

#include "services/tool_formats/fusion_format.h"

namespace mx::app::fusion {

namespace {

struct PresetField {
  NumberField number;
  std::optional<double> CuttingPresetSpec::*member;
  const char* expression;  // Fusion's expression for the value; dropped when the value changes
};

const std::array<PresetField, 6>& presetFields() {
  static const std::array<PresetField, 6> fields{{
      {{"n", Quantity::Speed, rules::kPresetSpeedRpm, true}, &CuttingPresetSpec::speed_rpm, "tool_spindleSpeed"},
      {{"v_c", Quantity::SurfaceSpeed, rules::kSurfaceSpeedMMin, true},
       &CuttingPresetSpec::surface_speed_m_min,
       "tool_surfaceSpeed"},
      {{"f_z", Quantity::Length, rules::kFeedPerToothMm, true},
       &CuttingPresetSpec::feed_per_tooth_mm,
       "tool_feedPerTooth"},
      {{"v_f", Quantity::Feed, rules::kPresetFeedMmMin, true}, &CuttingPresetSpec::feed_mm_min, "tool_feedCutting"},
      {{"stepdown", Quantity::Length, rules::kPresetDepthMm, true},
       &CuttingPresetSpec::axial_depth_mm,
       "tool_stepdown"},
      {{"stepover", Quantity::Length, rules::kPresetDepthMm, true},
       &CuttingPresetSpec::radial_depth_mm,
       "tool_stepover"},
  }};
  return fields;
}

const QString kNameKey = QStringLiteral("name");
const QString kExpressionsKey = QStringLiteral("expressions");

QString defaultName(qsizetype index) {
  return QString("Preset %1").arg(index + 1);
}

// The project needs a name; Fusion allows an empty one.
QString nameOf(const QJsonValue& name, qsizetype index) {
  return name.isString() && !name.toString().trimmed().isEmpty() ? name.toString() : defaultName(index);
}

CuttingPresetSpec readPreset(const QJsonObject& preset, qsizetype index, Unit unit, const Place& place,
                             const QString& path) {
  CuttingPresetSpec spec;
  spec.unknown = preset;
  const QJsonValue name = preset.value(kNameKey);
  if (!name.isUndefined() && !name.isNull() && !name.isString()) fail(place, path + ".name", "must be a string");
  spec.name = nameOf(name, index);
  spec.unknown.remove(kNameKey);
  for (const PresetField& field : presetFields()) {
    const std::optional<double> value =
        readNumber(preset, field.number, unit, place, QString("%1.%2").arg(path, field.number.key));
    if (!value) continue;
    spec.*field.member = value;
    spec.unknown.remove(field.number.key);
  }
  return spec;
}

void dropExpression(QJsonObject& object, const char* name) {
  QJsonObject expressions = object.value(kExpressionsKey).toObject();
  if (!expressions.contains(name)) return;
  expressions.remove(name);
  object.insert(kExpressionsKey, expressions);
}

QJsonObject presetToWrite(const CuttingPresetSpec& preset, const QJsonObject& origin, qsizetype index, Unit unit) {
  QJsonObject out = preset.unknown;
  const QJsonValue origin_name = origin.value(kNameKey);
  out.insert(kNameKey, nameOf(origin_name, index) == preset.name ? origin_name : QJsonValue(preset.name));
  for (const PresetField& field : presetFields()) {
    const std::optional<double>& value = preset.*field.member;
    if (!value) continue;
    const QJsonValue written = numberToWrite(origin.value(field.number.key), *value, field.number, unit);
    out.insert(field.number.key, written);
    if (written != origin.value(field.number.key)) dropExpression(out, field.expression);
  }
  return out;
}

}  // namespace

std::vector<CuttingPresetSpec> readPresets(const QJsonObject& tool, Unit unit, const Place& place) {
  const QJsonValue start = tool.value("start-values");
  if (start.isUndefined() || start.isNull()) return {};
  if (!start.isObject()) fail(place, "start-values", "must be an object");
  const QJsonValue list = start.toObject().value("presets");
  if (list.isUndefined() || list.isNull()) return {};
  if (!list.isArray()) fail(place, "start-values.presets", "must be an array");
  const QJsonArray presets = list.toArray();
  if (presets.size() > rules::kMaxCuttingPresets)
    fail(place, "start-values.presets",
         QString("%1 presets; at most %2 are read").arg(presets.size()).arg(rules::kMaxCuttingPresets));
  std::vector<CuttingPresetSpec> out;
  out.reserve(static_cast<std::size_t>(presets.size()));
  for (qsizetype i = 0; i < presets.size(); ++i) {
    const QString path = indexPath("start-values.presets", i);
    if (!presets.at(i).isObject()) fail(place, path, "must be an object");
    out.push_back(readPreset(presets.at(i).toObject(), i, unit, place, path));
  }
  return out;
}

QJsonArray presetsToWrite(const std::vector<CuttingPresetSpec>& presets, const QJsonArray& origin, Unit unit) {
  QJsonArray out;
  for (std::size_t i = 0; i < presets.size(); ++i) {
    const auto index = static_cast<qsizetype>(i);
    out.append(
        presetToWrite(presets[i], index < origin.size() ? origin.at(index).toObject() : QJsonObject{}, index, unit));
  }
  return out;
}

}  // namespace mx::app::fusion
