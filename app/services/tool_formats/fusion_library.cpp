#include "services/tool_formats/fusion_library.h"

#include <QJsonArray>
#include <QJsonDocument>

#include "services/tool_formats/fusion_format.h"
#include "services/tool_formats/zip_archive.h"

namespace mx::app {

namespace {

using fusion::Place;

QByteArray libraryJson(const QByteArray& bytes, const QString& fileName) {
  if (!looksLikeZip(bytes)) return bytes;
  try {
    return readSingleJsonEntry(bytes);
  } catch (const ZipArchiveError& e) {
    throw ToolLibraryError(
        toolLibraryError(fileName, {}, {}, QString("not a readable Fusion .tools archive: %1").arg(e.what())));
  }
}

QJsonArray libraryEntries(const QJsonObject& root, const QString& fileName) {
  const QJsonValue data = root.value("data");
  if (!data.isArray())
    throw ToolLibraryError(
        toolLibraryError(fileName, {}, "data", "missing or not an array (a Fusion library is {\"data\": [tools]})"));
  QJsonArray entries = data.toArray();
  if (entries.size() > kMaxFusionEntries)
    throw ToolLibraryError(toolLibraryError(
        fileName, {}, "data", QString("%1 entries; at most %2 are read").arg(entries.size()).arg(kMaxFusionEntries)));
  return entries;
}

// The origin keeps the whole record but MillExpert's own key, and names the unit it was read in
// when that came from the library, so that the record reads the same on its own.
QJsonObject originRecord(QJsonObject record, fusion::Unit unit) {
  record.remove(kFusionPayloadKey);
  if (!record.contains("unit") && !record.value("expressions").toObject().contains("tool_unit"))
    record.insert("unit", fusion::unitName(unit));
  return record;
}

ToolSpec readTool(const QJsonObject& record, const std::optional<QJsonValue>& libraryUnit, Place place) {
  const std::optional<QString> id = fusion::toolId(record, place);
  if (!id)
    fusion::fail(place, "description",
                 "missing (a tool without a post-process.number > 0 is named by its description or guid)");
  place.tool = *id;
  const fusion::Unit unit = fusion::toolUnit(record, libraryUnit, place);
  ToolSpec tool = fusion::readMillingTool(record, *id, unit, place);
  tool.origin = ToolOriginSpec{"fusion", originRecord(record, unit)};
  const QJsonValue payload = record.value(kFusionPayloadKey);
  if (payload.isUndefined() || payload.isNull()) {
    validateImportedTool(tool, place.file);
    return tool;
  }
  if (!payload.isObject()) fusion::fail(place, kFusionPayloadKey, "must be an object (MillExpert's tool dynamics)");
  return withPayload(tool, payload.toObject(), place.file);
}

}  // namespace

ImportedLibrary readFusionLibrary(const QByteArray& bytes, const QString& fileName) {
  QJsonParseError parse{};
  const QJsonDocument document = QJsonDocument::fromJson(libraryJson(bytes, fileName), &parse);
  if (parse.error != QJsonParseError::NoError)
    throw ToolLibraryError(toolLibraryError(
        fileName, {}, {}, QString("JSON syntax error at offset %1: %2").arg(parse.offset).arg(parse.errorString())));
  if (!document.isObject())
    throw ToolLibraryError(toolLibraryError(fileName, {}, {}, "not a Fusion tool library (an object with \"data\")"));
  const QJsonObject root = document.object();
  const QJsonArray entries = libraryEntries(root, fileName);
  std::optional<QJsonValue> library_unit;
  if (root.contains("unit")) library_unit = root.value("unit");

  ImportedLibrary library;
  for (qsizetype i = 0; i < entries.size(); ++i) {
    const QJsonObject record = entries.at(i).toObject();
    const Place place{fileName, fusion::toolLabel(record, i)};
    if (!entries.at(i).isObject()) fusion::fail(place, indexPath("data", i), "must be an object (a tool)");
    const QJsonValue type = record.value("type");
    if (!type.isString() || type.toString().trimmed().isEmpty())
      fusion::fail(place, "type", "missing (a Fusion tool type such as \"flat end mill\")");
    if (const std::optional<QString> reason = fusion::skipReason(type.toString())) {
      library.skipped.push_back({place.tool, *reason});
      continue;
    }
    library.tools.push_back(readTool(record, library_unit, place));
  }
  return library;
}

QByteArray writeFusionLibrary(const std::vector<ToolSpec>& tools, FusionContainer container) {
  QJsonArray data;
  for (const ToolSpec& tool : tools) {
    QJsonObject record = fusion::toolToWrite(tool);
    record.insert(kFusionPayloadKey, dynamicsPayload(tool));
    data.append(record);
  }
  QByteArray json = QJsonDocument(QJsonObject{{"data", data}}).toJson(QJsonDocument::Indented);
  if (container == FusionContainer::Json) return json;
  try {
    return writeSingleEntryZip(kFusionArchiveEntry, json);
  } catch (const ZipArchiveError& e) {
    throw ToolLibraryError(QString("Fusion .tools archive: %1").arg(e.what()));
  }
}

}  // namespace mx::app
