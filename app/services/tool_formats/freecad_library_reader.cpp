#include <QJsonArray>
#include <QJsonDocument>

#include "document/project_rules.h"
#include "document/shortened_text.h"
#include "services/tool_formats/freecad_bit.h"
#include "services/tool_formats/freecad_library.h"

namespace mx::app {

namespace {

[[noreturn]] void refuse(const QString& file, const QString& tool, const QString& field, const QString& what) {
  throw ToolLibraryError(toolLibraryError(file, tool, field, what));
}

QJsonArray libraryEntries(const QByteArray& fctl, const QString& file) {
  QJsonParseError parse{};
  const QJsonDocument doc = QJsonDocument::fromJson(fctl, &parse);
  if (parse.error != QJsonParseError::NoError)
    refuse(file, {}, {}, QString("JSON syntax error at offset %1: %2").arg(parse.offset).arg(parse.errorString()));
  if (!doc.isObject()) refuse(file, {}, {}, "must be a JSON object (a FreeCAD tool library)");
  const QJsonValue tools = doc.object().value("tools");
  if (!tools.isArray()) refuse(file, {}, "tools", "must be the array of the library's bits ({\"nr\", \"path\"})");
  QJsonArray entries = tools.toArray();
  if (entries.size() > kMaxFreeCadLibraryTools)
    refuse(file, {}, "tools", QString("%1 bits: at most %2").arg(entries.size()).arg(kMaxFreeCadLibraryTools));
  return entries;
}

// FreeCAD reads the number with int(): an integer, or a string of one.
int toolNumber(const QJsonValue& value, const QString& file, const QString& field) {
  bool ok = value.isDouble();
  double number = value.toDouble();
  if (value.isString()) number = value.toString().trimmed().toDouble(&ok);
  if (!ok || !rules::kCountAtLeastZero.accepts(number) || number > 2147483647.0)
    refuse(file, {}, field, QString("%1: must be a tool number, an integer >= 0").arg(formatValue(value)));
  return static_cast<int>(number);
}

QByteArray loadedBit(const FreeCadBitLoader& loadBit, const QString& path, const QString& file, const QString& tool,
                     const QString& field) {
  try {
    return loadBit(path);
  } catch (const ToolLibraryError& e) {
    refuse(file, tool, field, QString::fromUtf8(e.what()));
  }
}

}  // namespace

ImportedLibrary readFreeCadLibrary(const QByteArray& fctl, const QString& fileName, const FreeCadBitLoader& loadBit,
                                   const ToolImportOptions& options) {
  const QJsonArray entries = libraryEntries(fctl, fileName);
  ImportedLibrary library;
  for (qsizetype i = 0; i < entries.size(); ++i) {
    const QString field = indexPath("tools", i);
    if (!entries.at(i).isObject()) refuse(fileName, {}, field, "must be an object {\"nr\", \"path\"}");
    const QJsonObject entry = entries.at(i).toObject();
    const int nr = toolNumber(entry.value("nr"), fileName, field + ".nr");
    const QString id = QString("T%1").arg(nr);
    const QString path = entry.value("path").toString();
    if (path.trimmed().isEmpty()) refuse(fileName, id, field + ".path", "must name the bit's file (\"endmill.fctb\")");
    const QByteArray bytes = loadedBit(loadBit, path, fileName, id, field + ".path");
    const FreeCadBitImport bit = importFreeCadBit(bytes, path, {nr, freeCadBitFileName(path)}, options);
    if (bit.tool) library.tools.push_back(*bit.tool);
    if (bit.skipped) library.skipped.push_back(*bit.skipped);
  }
  return library;
}

}  // namespace mx::app
