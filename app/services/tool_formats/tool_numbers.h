#pragma once
// Tool numbers of an export to a format that numbers its tools (a FreeCAD library's "nr", a LinuxCNC
// T word). An import names a numbered tool "T<number>", so an export gives each tool the number of its
// id when the id is one, else the number it was imported with, else the lowest number still free. Ids
// are served before imported numbers; a number asked for twice goes to the first tool asking.
#include <QString>
#include <optional>
#include <vector>

#include "document/project.h"

namespace mx::app {

// 7 for "T7" (tool numbers are non-negative 32-bit integers), nullopt for any other id.
std::optional<int> toolNumberOfId(const QString& id);

// One number per tool, all different. `imported` gives the number a tool was imported with, if any.
std::vector<int> exportToolNumbers(const std::vector<ToolSpec>& tools,
                                   std::optional<int> (*imported)(const ToolSpec& tool));

}  // namespace mx::app
