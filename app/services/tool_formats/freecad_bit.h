#pragma once
// One FreeCAD bit to one tool, and what the reader and the writer share about the bit's record.
#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <optional>

#include "services/tool_formats/tool_library_io.h"

namespace mx::app {

// MillExpert's data in a bit: attribute.MillExpert, a JSON text (an object is read too). FreeCAD turns
// an attribute it does not know into a string property and saves it under "parameter" (ToolBit.to_dict),
// so a text survives a save in FreeCAD where an object would not; the reader looks in both places.
inline const QString kFreeCadPayloadKey = QStringLiteral("MillExpert");

// The project keys the payload may carry besides the dynamics: what a bit had no parameter for.
const QStringList& freeCadCarriedKeys();

// Where a bit was found: its library entry's number (none for a lone bit) and its file's name.
struct FreeCadBitPlace {
  std::optional<int> nr;
  QString path;
};

struct FreeCadBitImport {
  std::optional<ToolSpec> tool;
  std::optional<SkippedTool> skipped;
};

// The tool of one bit ("T<nr>" in a library, else the bit's name, else the file's base name), or the
// reason it is skipped. Errors name `bitFile`, the tool and the field.
FreeCadBitImport importFreeCadBit(const QByteArray& fctb, const QString& bitFile, const FreeCadBitPlace& place,
                                  const ToolImportOptions& options);

// The bit file a library entry's path names, as the writer names it: the last path component, control
// characters replaced by '_', ".fctb" appended when missing; empty for no usable name ("", "..", too long).
// ToolSpec::origin keeps this name, so that an export writes the bit under the name it had.
QString freeCadBitFileName(const QString& reference);

// The bit without MillExpert's data and without an empty "attribute": what ToolSpec::origin keeps.
QJsonObject withoutFreeCadPayload(QJsonObject bit);

}  // namespace mx::app
