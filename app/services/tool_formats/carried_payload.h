#pragma once
// The MillExpert data a FreeCAD bit or a LinuxCNC table carries for a tool: the dynamics payload
// (tool_library_io.h) and the tool's project keys the format has no place for (a LinuxCNC table has
// no flute count, a FreeCAD endmill no corner radius, neither a stickout). On import the format's own
// values win; the carried keys fill only what the format did not give.
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <optional>

#include "services/tool_formats/tool_library_io.h"

namespace mx::app {

// dynamicsPayload(tool) and, of `keys` (project keys: "teeth", "flute_length_mm", ...), those the tool has.
QJsonObject carriedPayload(const ToolSpec& tool, const QStringList& keys);

// The payload's "teeth", when it carries one; throws ToolLibraryError naming `file`, `tool` and
// `field` (+ ".teeth") when it is not an integer in [1, 100].
std::optional<int> carriedTeeth(const QJsonObject& payload, const QString& file, const QString& tool,
                                const QString& field);

// `mapped` (its teeth already known) with the payload's `keys` that mapped lacks, then withPayload:
// the validated tool, or ToolLibraryError naming `file`, the tool and `field` for a bad carried value.
ToolSpec withCarriedPayload(const ToolSpec& mapped, const QJsonObject& payload, const QStringList& keys,
                            const QString& file, const QString& field);

// The teeth of an imported tool: the format's count, else the carried one, else --teeth.
std::optional<int> importedTeeth(std::optional<int> from_format, std::optional<int> carried,
                                 const ToolImportOptions& options);

}  // namespace mx::app
