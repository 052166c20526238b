#include "services/tool_formats/freecad_shapes.h"

#include <QStringList>

#include "document/shortened_text.h"

namespace mx::app {

namespace {

struct MillShapeEntry {
  FreeCadMillShape shape;
  QStringList aliases;  // lower case, as in shape_aliases.json
};

const std::vector<MillShapeEntry>& millShapes() {
  static const std::vector<MillShapeEntry> shapes{
      {{"Endmill", "endmill.fcstd", "flat end mill"}, {"endmill"}},
      {{"Ballend", "ballend.fcstd", "ball end mill"}, {"ballend"}},
      {{"Bullnose", "bullnose.fcstd", "bull nose end mill", true, true}, {"bullnose", "torus"}},
      {{"Chamfer", "chamfer.fcstd", "chamfer mill"}, {"chamfer"}},
      {{"VBit", "v-bit.fcstd", "chamfer mill"}, {"vbit", "v-bit", "v_bit"}},
      {{"SlittingSaw", "slittingsaw.fcstd", "slot mill", false}, {"slittingsaw", "slitting-saw", "slitting_saw"}},
      {{"ThreadMill", "thread-mill.fcstd", "thread mill", false}, {"threadmill", "thread-mill", "thread_mill"}},
      {{"Dovetail", "dovetail.fcstd", "dovetail mill"}, {"dovetail"}},
      {{"Radius", "radius.fcstd", "radius mill"}, {"radius", "fillet"}},
      {{"TaperedBallNose", "taperedballnose.fcstd", "tapered mill"},
       {"taperedballnose", "taperballnose", "conicalballnose"}},
  };
  return shapes;
}

struct OtherShapeEntry {
  QStringList aliases;
  const char* what;
};

// Shapes that do not mill: they make or gauge holes, or turn.
const std::vector<OtherShapeEntry>& otherShapes() {
  static const std::vector<OtherShapeEntry> shapes{
      {{"drill"}, "a drill"}, {{"tap"}, "a tap"}, {{"reamer"}, "a reamer"}, {{"probe"}, "a probe"}};
  return shapes;
}

// "C:\\Tools\\Shape\\v-bit.FCStd" -> "v-bit".
QString shapeStem(const QString& shape) {
  QString stem = shape.mid(std::max(shape.lastIndexOf('/'), shape.lastIndexOf('\\')) + 1).toLower();
  if (stem.endsWith(".fcstd")) stem.chop(6);
  return stem;
}

const MillShapeEntry* millShapeNamed(const QString& name) {
  const QString key = name.toLower();
  for (const MillShapeEntry& entry : millShapes())
    if (entry.shape.shape_type.toLower() == key || entry.aliases.contains(key)) return &entry;
  return nullptr;
}

const OtherShapeEntry* otherShapeNamed(const QString& name) {
  const QString key = name.toLower();
  for (const OtherShapeEntry& entry : otherShapes())
    if (entry.aliases.contains(key)) return &entry;
  return nullptr;
}

}  // namespace

FreeCadShapeLookup freeCadShape(const QJsonObject& bit) {
  const QString shape = bit.value("shape").toString();
  const QString shape_type = bit.value("shape-type").toString();
  const QString stem = shapeStem(shape);
  for (const QString& name : {shape_type, stem}) {
    if (name.isEmpty()) continue;
    if (const MillShapeEntry* mill = millShapeNamed(name)) return {mill->shape, {}};
    if (const OtherShapeEntry* other = otherShapeNamed(name))
      return {std::nullopt, QString("%1 (%2), not a milling cutter").arg(other->what, quoted(shape))};
  }
  if (stem.startsWith("iso"))
    return {std::nullopt, QString("a turning insert (%1), not a milling cutter").arg(quoted(shape))};
  return {std::nullopt, QString("the shape %1 is not a milling cutter FreeCAD defines").arg(quoted(shape))};
}

FreeCadMillShape freeCadShapeForType(const std::optional<QString>& type) {
  if (type)
    for (const MillShapeEntry& entry : millShapes())
      if (entry.shape.type == *type) return entry.shape;
  return millShapes().front().shape;
}

}  // namespace mx::app
