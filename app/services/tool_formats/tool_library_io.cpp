#include "services/tool_formats/tool_library_io.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>

#include "document/project_rules.h"
#include "document/project_validation.h"
#include "document/shortened_text.h"

namespace mx::app {

namespace {

constexpr auto kSideFileFormat = "millexpert-tool-dynamics";

// Keys the payload always decides: no CAM format has them.
const QStringList& ownedKeys() {
  static const QStringList keys{"modes_x",   "modes_y",  "frf_x",    "frf_y",    "Kt_N_mm2",        "Kr",
                                "Kte_N_mm",  "Kre_N_mm", "Ka_N_mm2", "Kae_N_mm", "radial_depth_mm", "max_force_N",
                                "pitch_deg", "runout_um"};
  return keys;
}

// "tools[0].modes_x[1].freq_Hz = -3: must be > 0" -> "modes_x[1].freq_Hz = -3: must be > 0".
QString withoutToolPrefix(const QString& message) {
  static const QString prefix = QStringLiteral("tools[0].");
  return message.startsWith(prefix) ? message.mid(prefix.size()) : message;
}

}  // namespace

QString toolLibraryError(const QString& file, const QString& tool, const QString& field, const QString& what) {
  QString where = QFileInfo(file).fileName();
  if (!tool.isEmpty()) where += QString(": tool %1").arg(quoted(tool));
  if (!field.isEmpty()) where += QString(", %1").arg(field);
  return where + ": " + what;
}

QJsonObject dynamicsPayload(const ToolSpec& tool) {
  const QJsonObject json = toolToJson(tool);
  QJsonObject payload;
  for (const QString& key : ownedKeys()) {
    const QJsonValue value = json.value(key);
    // A rigid axis (no modes) is what every format gives already.
    if (!value.isUndefined() && !(value.isArray() && value.toArray().isEmpty())) payload.insert(key, value);
  }
  if (tool.helix_deg != 0.0) payload.insert("helix_deg", json.value("helix_deg"));
  return payload;
}

void validateImportedTool(const ToolSpec& tool, const QString& file) {
  try {
    validateTools({tool}, std::nullopt);
  } catch (const ProjectError& e) {
    throw ToolLibraryError(toolLibraryError(file, tool.id, {}, withoutToolPrefix(QString::fromStdString(e.what()))));
  }
}

ToolSpec withPayload(const ToolSpec& mapped, const QJsonObject& payload, const QString& file) {
  QJsonObject json = toolToJson(mapped);
  for (const QString& key : ownedKeys()) {
    if (payload.contains(key)) json.insert(key, payload.value(key));
  }
  if (mapped.helix_deg == 0.0 && payload.contains("helix_deg")) json.insert("helix_deg", payload.value("helix_deg"));
  ToolSpec tool;
  try {
    tool = toolFromJson(json, QStringLiteral("tools[0]"));
  } catch (const ProjectError& e) {
    throw ToolLibraryError(toolLibraryError(file, mapped.id, {}, withoutToolPrefix(QString::fromStdString(e.what()))));
  }
  validateImportedTool(tool, file);
  return tool;
}

QString sideFilePath(const QString& libraryPath) {
  const QFileInfo info(libraryPath);
  const QString name = info.completeBaseName() + ".millexpert.json";
  return libraryPath.contains(u'/') ? info.dir().filePath(name) : name;
}

QByteArray writeSideFile(const std::vector<ToolSpec>& tools) {
  QJsonArray entries;
  for (const ToolSpec& tool : tools) {
    QJsonObject entry = dynamicsPayload(tool);
    entry.insert("id", tool.id);
    entries.append(entry);
  }
  const QJsonObject root{{"format", kSideFileFormat}, {"version", 1}, {"tools", entries}};
  return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

std::map<QString, QJsonObject> readSideFile(const QByteArray& bytes, const QString& fileName) {
  QJsonParseError parse{};
  const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parse);
  if (parse.error != QJsonParseError::NoError)
    throw ToolLibraryError(toolLibraryError(
        fileName, {}, {}, QString("JSON syntax error at offset %1: %2").arg(parse.offset).arg(parse.errorString())));
  const QJsonObject root = doc.object();
  if (root.value("format").toString() != kSideFileFormat)
    throw ToolLibraryError(toolLibraryError(
        fileName, {}, "format", QString("%1: must be \"%2\"").arg(formatValue(root.value("format")), kSideFileFormat)));
  if (!root.value("tools").isArray())
    throw ToolLibraryError(toolLibraryError(fileName, {}, "tools", "must be an array of tools"));
  std::map<QString, QJsonObject> payloads;
  const QJsonArray entries = root.value("tools").toArray();
  for (qsizetype i = 0; i < entries.size(); ++i) {
    const QString field = indexPath("tools", i);
    const QJsonObject entry = entries.at(i).toObject();
    const QString id = entry.value("id").toString();
    if (!entries.at(i).isObject() || id.trimmed().isEmpty())
      throw ToolLibraryError(toolLibraryError(fileName, {}, field + ".id", "must be a non-empty string"));
    if (payloads.count(id) != 0)
      throw ToolLibraryError(toolLibraryError(fileName, id, field + ".id", "repeats an earlier entry"));
    QJsonObject payload = entry;
    payload.remove("id");
    payloads.emplace(id, payload);
  }
  return payloads;
}

}  // namespace mx::app
