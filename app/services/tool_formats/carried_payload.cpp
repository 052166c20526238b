#include "services/tool_formats/carried_payload.h"

#include <QJsonArray>

#include "document/project_rules.h"

namespace mx::app {

namespace {

const QString kTeeth = QStringLiteral("teeth");

// "tools[0].flute_length_mm = -3: must be > 0" -> "flute_length_mm = -3: must be > 0".
QString withoutToolPath(const QString& message) {
  static const QString prefix = QStringLiteral("tools[0].");
  return message.startsWith(prefix) ? message.mid(prefix.size()) : message;
}

}  // namespace

QJsonObject carriedPayload(const ToolSpec& tool, const QStringList& keys) {
  QJsonObject payload = dynamicsPayload(tool);
  // A rigid axis has no modes: an empty list carries nothing, and no payload keeps a bit unchanged.
  for (const char* axis : {"modes_x", "modes_y"})
    if (payload.value(axis).toArray().isEmpty()) payload.remove(axis);
  const QJsonObject json = toolToJson(tool);
  for (const QString& key : keys)
    if (json.contains(key)) payload.insert(key, json.value(key));
  return payload;
}

std::optional<int> carriedTeeth(const QJsonObject& payload, const QString& file, const QString& tool,
                                const QString& field) {
  if (!payload.contains(kTeeth)) return std::nullopt;
  const QJsonValue value = payload.value(kTeeth);
  if (!value.isDouble() || !rules::kTeeth.accepts(value.toDouble()))
    throw ToolLibraryError(toolLibraryError(file, tool, field.isEmpty() ? kTeeth : field + ".teeth",
                                            QString("%1: %2").arg(formatValue(value), rules::kTeeth.mustBe(0))));
  return static_cast<int>(value.toDouble());
}

ToolSpec withCarriedPayload(const ToolSpec& mapped, const QJsonObject& payload, const QStringList& keys,
                            const QString& file, const QString& field) {
  QJsonObject json = toolToJson(mapped);
  for (const QString& key : keys)
    if (key != kTeeth && !json.contains(key) && payload.contains(key)) json.insert(key, payload.value(key));
  ToolSpec tool;
  try {
    tool = toolFromJson(json, QStringLiteral("tools[0]"));
  } catch (const ProjectError& e) {
    throw ToolLibraryError(toolLibraryError(file, mapped.id, field, withoutToolPath(QString::fromUtf8(e.what()))));
  }
  return withPayload(tool, payload, file);
}

std::optional<int> importedTeeth(std::optional<int> from_format, std::optional<int> carried,
                                 const ToolImportOptions& options) {
  if (from_format) return from_format;
  if (carried) return carried;
  return options.teeth;
}

}  // namespace mx::app
