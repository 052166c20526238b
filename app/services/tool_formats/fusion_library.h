#pragma once
// Fusion 360 tool libraries (docs/tool-libraries.md, "Fusion 360"): the JSON library
// {"data": [tool, ...]} and the `.tools` file, a zip archive holding that JSON. Milling cutters import
// as project tools (geometry, flutes, cutting presets, converted from inches when the tool is in
// inches); drills, taps, probes, holders and lathe tools are skipped with the reason. Each tool keeps
// its whole Fusion record as its origin, so that an export starts from it and overwrites only what
// MillExpert maps; MillExpert's dynamics travel in the tool's "millexpert" key.
#include <QByteArray>
#include <QString>
#include <vector>

#include "document/project.h"
#include "services/tool_formats/tool_library_io.h"

namespace mx::app {

// The key of a Fusion tool object that holds dynamicsPayload(tool).
inline constexpr auto kFusionPayloadKey = "millexpert";
// The name of the JSON entry of a written `.tools` archive.
inline constexpr auto kFusionArchiveEntry = "tools.json";
// Entries of "data" read at most (the file's size limit keeps far fewer in practice).
inline constexpr qsizetype kMaxFusionEntries = 100000;

// The whole library, all or nothing: a zip (detected by its first bytes, not by `fileName`) is
// unpacked first. Throws ToolLibraryError naming `fileName`, the tool and the field.
ImportedLibrary readFusionLibrary(const QByteArray& bytes, const QString& fileName);

enum class FusionContainer { Json, Zipped };

// The tools as a Fusion library. A tool imported from Fusion starts from its origin record; another
// one is written in millimetres as a new record. Throws ToolLibraryError when a tool's origin record
// has no readable unit, or the archive cannot be written.
QByteArray writeFusionLibrary(const std::vector<ToolSpec>& tools, FusionContainer container);

}  // namespace mx::app
