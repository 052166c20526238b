#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>

#include "document/project_rules.h"
#include "services/tool_formats/carried_payload.h"
#include "services/tool_formats/freecad_bit.h"
#include "services/tool_formats/freecad_geometry.h"
#include "services/tool_formats/freecad_library.h"
#include "services/tool_formats/freecad_quantity.h"
#include "services/tool_formats/tool_numbers.h"

namespace mx::app {

namespace {

// One mapped field of a bit: where the reader finds it, what the writer writes, and the tool's value.
struct BitField {
  QStringList parameters;  // the names the reader accepts; the first is written
  FreeCadField FreeCadGeometry::*read;
  std::optional<double> wanted;
  QString carried_key;  // the project key carried when the bit does not give the tool's value
  bool count = false;   // Flutes: an integer, not a length
};

std::vector<BitField> bitFields(const ToolSpec& tool) {
  return {
      {{"Diameter"}, &FreeCadGeometry::diameter, tool.diameter_mm, {}},
      {{"Flutes"}, &FreeCadGeometry::flutes, static_cast<double>(tool.teeth), "teeth", true},
      {{"CuttingEdgeHeight"}, &FreeCadGeometry::cutting_edge_height, tool.flute_length_mm, "flute_length_mm"},
      {{"Length"}, &FreeCadGeometry::length, tool.overall_length_mm, "overall_length_mm"},
      {{"CornerRadius", "TorusRadius", "FlatRadius"},
       &FreeCadGeometry::corner_radius,
       tool.corner_radius_mm,
       "corner_radius_mm"},
  };
}

bool shapeHolds(const BitField& field, const FreeCadMillShape& shape) {
  if (field.read == &FreeCadGeometry::cutting_edge_height) return shape.has_cutting_edge_height;
  if (field.read == &FreeCadGeometry::corner_radius) return shape.has_corner_radius;
  return true;
}

bool fromFreeCad(const ToolSpec& tool) {
  return tool.origin && tool.origin->format == "freecad" && tool.origin->data.value("bit").isObject();
}

QJsonObject freshBit(const ToolSpec& tool, const FreeCadMillShape& shape) {
  return {{"version", 2},
          {"name", tool.id},
          {"shape", shape.file},
          {"shape-type", shape.shape_type},
          {"parameter", QJsonObject{}}};
}

// Sets one field of `parameters` to the tool's value. A parameter whose value is already the tool's
// keeps its text ("0.2500 in" stays). A bit from FreeCAD that never gave the field (absent, or unset 0)
// stays so, and the value is carried instead: the bit then reads back to the same origin.
void updateField(QJsonObject& parameters, const BitField& field, const FreeCadMillShape& shape, bool fresh) {
  const FreeCadField current = readFreeCadGeometry(parameters, shape).*field.read;
  if (current.problem.isEmpty() && current.value == field.wanted) return;
  const bool gives = current.value.has_value() || !current.problem.isEmpty();
  if (!field.wanted) {
    for (const QString& name : field.parameters) parameters.remove(name);
    return;
  }
  if (!shapeHolds(field, shape) || !(fresh || gives || field.carried_key.isEmpty())) return;
  const QString name = field.parameters.front();
  if (field.count) {
    parameters.insert(name, static_cast<int>(*field.wanted));
  } else {
    for (const QString& other : field.parameters) parameters.remove(other);
    parameters.insert(name, freeCadLengthText(*field.wanted));
  }
}

// The bit of a tool: its FreeCAD record, the tool's values written over it, MillExpert's data in
// attribute.MillExpert (what the bit does not give: the dynamics and the unheld values).
QJsonObject exportedBit(const ToolSpec& tool) {
  QJsonObject bit =
      fromFreeCad(tool) ? withoutFreeCadPayload(tool.origin->data.value("bit").toObject()) : QJsonObject{};
  FreeCadShapeLookup shape = freeCadShape(bit);
  const bool fresh = !shape.mill.has_value();
  if (fresh) {
    shape.mill = freeCadShapeForType(tool.type);
    bit = freshBit(tool, *shape.mill);
  }
  QJsonObject parameters = bit.value("parameter").toObject();
  const std::vector<BitField> fields = bitFields(tool);
  for (const BitField& field : fields) updateField(parameters, field, *shape.mill, fresh);
  bit.insert("parameter", parameters);

  QStringList carried{"stickout_mm", "cutting_data"};
  const FreeCadGeometry written = readFreeCadGeometry(parameters, *shape.mill);
  for (const BitField& field : fields)
    if (!field.carried_key.isEmpty() && (written.*field.read).value != field.wanted) carried.append(field.carried_key);
  QJsonObject attributes = bit.value("attribute").toObject();
  const QJsonObject payload = carriedPayload(tool, carried);
  if (!payload.isEmpty())
    attributes.insert(kFreeCadPayloadKey, QString::fromUtf8(QJsonDocument(payload).toJson(QJsonDocument::Compact)));
  bit.insert("attribute", attributes);
  return bit;
}

std::optional<int> importedNumber(const ToolSpec& tool) {
  if (!fromFreeCad(tool) || !tool.origin->data.value("nr").isDouble()) return std::nullopt;
  const double nr = tool.origin->data.value("nr").toDouble();
  if (!rules::kCountAtLeastZero.accepts(nr) || nr > 2147483647.0) return std::nullopt;
  return static_cast<int>(nr);
}

// The bit's file name: the one it was imported from, else one made from the tool's id.
QString wantedFileName(const ToolSpec& tool) {
  if (fromFreeCad(tool)) {
    QString imported = freeCadBitFileName(tool.origin->data.value("path").toString());
    if (!imported.isEmpty()) return imported;
  }
  QString stem = tool.id;
  stem.replace('/', '_').replace('\\', '_');
  const QString name = freeCadBitFileName(stem.left(100));
  return name.isEmpty() ? QStringLiteral("tool.fctb") : name;
}

// Bits with the same file name and the same content are written once (a library may hold one bit in
// several pockets); a different bit under a taken name gets "-2", "-3", ... Names compare without case,
// for the file systems that ignore it.
class BitFiles {
 public:
  QString add(const QString& wanted, const QByteArray& content) {
    QString name = wanted;
    for (int n = 2; taken_.contains(name.toLower()); ++n) {
      if (content_.value(name.toLower()) == content) return name;
      name = wanted.chopped(5) + QString("-%1.fctb").arg(n);
    }
    taken_.insert(name.toLower());
    content_.insert(name.toLower(), content);
    files_.emplace_back(kFreeCadBitFolder + '/' + name, content);
    return name;
  }
  std::vector<std::pair<QString, QByteArray>> files() const { return files_; }

 private:
  QSet<QString> taken_;
  QHash<QString, QByteArray> content_;
  std::vector<std::pair<QString, QByteArray>> files_;
};

QString libraryFileStem(const QString& libraryName) {
  QString stem = libraryName;
  stem.replace('/', '_').replace('\\', '_');
  for (QChar& c : stem)
    if (c.unicode() < 0x20 || c.unicode() == 0x7f) c = u'_';
  if (stem.trimmed().isEmpty() || stem == "." || stem == "..") return QStringLiteral("MillExpert");
  return stem.left(100);
}

}  // namespace

FreeCadExport writeFreeCadLibrary(const std::vector<ToolSpec>& tools, const QString& libraryName) {
  const std::vector<int> numbers = exportToolNumbers(tools, importedNumber);
  BitFiles files;
  QJsonArray entries;
  for (std::size_t i = 0; i < tools.size(); ++i) {
    const QByteArray bit = QJsonDocument(exportedBit(tools[i])).toJson(QJsonDocument::Indented);
    const QString name = files.add(wantedFileName(tools[i]), bit);
    entries.append(QJsonObject{{"nr", numbers[i]}, {"path", name}});
  }
  const QJsonObject library{{"tools", entries}, {"version", 1}};
  return {QJsonDocument(library).toJson(QJsonDocument::Indented), libraryFileStem(libraryName), files.files()};
}

}  // namespace mx::app
