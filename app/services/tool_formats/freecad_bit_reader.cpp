#include <QFileInfo>
#include <QJsonDocument>

#include "document/project_rules.h"
#include "document/shortened_text.h"
#include "services/tool_formats/carried_payload.h"
#include "services/tool_formats/freecad_bit.h"
#include "services/tool_formats/freecad_geometry.h"
#include "services/tool_formats/freecad_library.h"
#include "services/tool_formats/freecad_shapes.h"

namespace mx::app {

namespace {

[[noreturn]] void refuse(const QString& file, const QString& tool, const QString& field, const QString& what) {
  throw ToolLibraryError(toolLibraryError(file, tool, field, what));
}

QJsonObject bitObject(const QByteArray& fctb, const QString& file) {
  QJsonParseError parse{};
  const QJsonDocument doc = QJsonDocument::fromJson(fctb, &parse);
  if (parse.error != QJsonParseError::NoError)
    refuse(file, {}, {}, QString("JSON syntax error at offset %1: %2").arg(parse.offset).arg(parse.errorString()));
  if (!doc.isObject()) refuse(file, {}, {}, "must be a JSON object (a FreeCAD tool bit)");
  return doc.object();
}

// "T<nr>" in a library; a lone bit is named by its "name", else by its file.
QString toolId(const QJsonObject& bit, const QString& file, const FreeCadBitPlace& place) {
  if (place.nr) return QString("T%1").arg(*place.nr);
  QString name = bit.value("name").toString();
  if (!name.trimmed().isEmpty()) return name;
  const QString stem = QFileInfo(file).completeBaseName();
  return stem.trimmed().isEmpty() ? QStringLiteral("bit") : stem;
}

void checkTypes(const QJsonObject& bit, const QString& file, const QString& id) {
  for (const char* key : {"name", "shape", "shape-type"})
    if (bit.contains(key) && !bit.value(key).isString()) refuse(file, id, key, "must be a string");
  for (const char* key : {"parameter", "attribute"})
    if (bit.contains(key) && !bit.value(key).isObject()) refuse(file, id, key, "must be an object");
  if (!bit.contains("shape") && !bit.contains("shape-type"))
    refuse(file, id, "shape", "missing: a bit names its shape (\"endmill.fcstd\")");
}

struct FoundPayload {
  QJsonObject payload;
  QString field = QStringLiteral("attribute.") + kFreeCadPayloadKey;
};

FoundPayload payloadOf(const QJsonObject& bit, const QString& file, const QString& id) {
  for (const char* section : {"attribute", "parameter"}) {
    const QJsonObject values = bit.value(section).toObject();
    if (!values.contains(kFreeCadPayloadKey)) continue;
    const QString field = QString("%1.%2").arg(section, kFreeCadPayloadKey);
    const QJsonValue value = values.value(kFreeCadPayloadKey);
    if (value.isObject()) return {value.toObject(), field};
    QJsonParseError parse{};
    const QJsonDocument doc = QJsonDocument::fromJson(value.toString().toUtf8(), &parse);
    if (!value.isString() || parse.error != QJsonParseError::NoError || !doc.isObject())
      refuse(file, id, field, "must be MillExpert's tool data, a JSON object or its text");
    return {doc.object(), field};
  }
  return {};
}

double requiredValue(const FreeCadField& field, const QString& file, const QString& id) {
  if (!field.problem.isEmpty()) refuse(file, id, "parameter." + field.parameter, field.problem);
  return *field.value;
}

std::optional<double> optionalValue(const FreeCadField& field, const QString& file, const QString& id) {
  if (!field.problem.isEmpty()) refuse(file, id, "parameter." + field.parameter, field.problem);
  return field.value;
}

QJsonObject originData(const QJsonObject& bit, const FreeCadBitPlace& place) {
  QJsonObject data{{"bit", withoutFreeCadPayload(bit)}, {"path", place.path}};
  if (place.nr) data.insert("nr", *place.nr);
  return data;
}

ToolSpec mappedTool(const QJsonObject& bit, const FreeCadMillShape& shape, const QString& file, const QString& id,
                    const FreeCadBitPlace& place) {
  const FreeCadGeometry g = readFreeCadGeometry(bit.value("parameter").toObject(), shape);
  ToolSpec tool;
  tool.id = id;
  tool.diameter_mm = requiredValue(g.diameter, file, id);
  if (const std::optional<double> flutes = optionalValue(g.flutes, file, id)) tool.teeth = static_cast<int>(*flutes);
  tool.flute_length_mm = optionalValue(g.cutting_edge_height, file, id);
  tool.overall_length_mm = optionalValue(g.length, file, id);
  tool.corner_radius_mm = optionalValue(g.corner_radius, file, id);
  tool.type = shape.type;
  tool.origin = ToolOriginSpec{QStringLiteral("freecad"), originData(bit, place)};
  return tool;
}

}  // namespace

const QStringList& freeCadCarriedKeys() {
  static const QStringList keys{"teeth",       "flute_length_mm", "overall_length_mm", "corner_radius_mm",
                                "stickout_mm", "cutting_data"};
  return keys;
}

QString freeCadBitFileName(const QString& reference) {
  constexpr qsizetype kMaxNameChars = 150;  // with any suffix, within every file system's 255 bytes
  QString name = reference.mid(std::max(reference.lastIndexOf('/'), reference.lastIndexOf('\\')) + 1);
  for (QChar& c : name)
    if (c.unicode() < 0x20 || c.unicode() == 0x7f) c = u'_';
  if (name.isEmpty() || name == "." || name == "..") return {};
  if (!name.endsWith(".fctb", Qt::CaseInsensitive)) name += ".fctb";
  return name.size() > kMaxNameChars ? QString() : name;
}

QJsonObject withoutFreeCadPayload(QJsonObject bit) {
  for (const char* section : {"attribute", "parameter"}) {
    if (!bit.value(section).isObject()) continue;
    QJsonObject values = bit.value(section).toObject();
    values.remove(kFreeCadPayloadKey);
    bit.insert(section, values);
  }
  // The writer always writes "attribute"; without it when empty, a bit reads back to the same origin.
  if (bit.value("attribute").toObject().isEmpty() && bit.value("attribute").isObject()) bit.remove("attribute");
  return bit;
}

FreeCadBitImport importFreeCadBit(const QByteArray& fctb, const QString& bitFile, const FreeCadBitPlace& place,
                                  const ToolImportOptions& options) {
  const QJsonObject bit = bitObject(fctb, bitFile);
  const QString id = toolId(bit, bitFile, place);
  checkTypes(bit, bitFile, id);
  const FreeCadShapeLookup shape = freeCadShape(bit);
  if (!shape.mill) {
    const QString name = bit.value("name").toString();
    const bool named_otherwise = !name.trimmed().isEmpty() && name != id;
    return {std::nullopt, SkippedTool{id, (named_otherwise ? quoted(name) + ": " : QString()) + shape.skip_reason}};
  }
  const FoundPayload found = payloadOf(bit, bitFile, id);
  ToolSpec tool = mappedTool(bit, *shape.mill, bitFile, id, place);
  const std::optional<int> teeth = importedTeeth(tool.teeth > 0 ? std::optional<int>(tool.teeth) : std::nullopt,
                                                 carriedTeeth(found.payload, bitFile, id, found.field), options);
  if (!teeth)
    refuse(bitFile, id, "parameter.Flutes",
           "missing: the bit gives no flute count; add \"Flutes\" to the bit or give --teeth N");
  if (!rules::kTeeth.accepts(*teeth)) refuse(bitFile, id, "--teeth", rules::kTeeth.mustBe(*teeth));
  tool.teeth = *teeth;
  return {withCarriedPayload(tool, found.payload, freeCadCarriedKeys(), bitFile, found.field), std::nullopt};
}

ImportedLibrary readFreeCadBit(const QByteArray& fctb, const QString& fileName, const ToolImportOptions& options) {
  const FreeCadBitImport bit = importFreeCadBit(fctb, fileName, {std::nullopt, freeCadBitFileName(fileName)}, options);
  ImportedLibrary library;
  if (bit.tool) library.tools.push_back(*bit.tool);
  if (bit.skipped) library.skipped.push_back(*bit.skipped);
  return library;
}

}  // namespace mx::app
