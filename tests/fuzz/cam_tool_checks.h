#pragma once
// Promises shared by the FreeCAD and LinuxCNC targets: every accepted tool is finite and valid on its
// own (a library may repeat a tool number: the merge into a project renames), a skipped tool says why,
// and two tool lists agree with or without their ids and origin records.
#include <QJsonDocument>
#include <algorithm>
#include <cstdio>
#include <vector>

#include "services/tool_formats/tool_library_io.h"
#include "tool_checks.h"

namespace mx::fuzz {

inline void requireValidCamTools(const app::ImportedLibrary& library) {
  for (const app::ToolSpec& tool : library.tools) {
    for (const auto& v : {tool.flute_length_mm, tool.overall_length_mm, tool.stickout_mm, tool.corner_radius_mm})
      if (v) requireFinite(*v, "an accepted tool holds finite numbers only");
    requireValidTools({tool});
  }
  for (const app::SkippedTool& skipped : library.skipped)
    require(!skipped.name.isEmpty() && !skipped.reason.isEmpty(), "a skipped tool has a name and a reason");
}

inline bool idsUnique(const std::vector<app::ToolSpec>& tools) {
  for (std::size_t i = 0; i < tools.size(); ++i)
    for (std::size_t j = i + 1; j < tools.size(); ++j)
      if (tools[i].id == tools[j].id) return false;
  return true;
}

// The tools as an export cannot but change them when it renumbers or renames: without id and origin.
inline std::vector<app::ToolSpec> anonymous(std::vector<app::ToolSpec> tools) {
  for (app::ToolSpec& tool : tools) {
    tool.id.clear();
    tool.origin.reset();
  }
  return tools;
}

inline void requireSameTools(const std::vector<app::ToolSpec>& got, const std::vector<app::ToolSpec>& expected,
                             const char* what) {
  if (got == expected) return;
  for (std::size_t i = 0; i < std::min(got.size(), expected.size()); ++i)
    if (!(got[i] == expected[i]))
      std::fprintf(stderr, "fuzz: tool %zu differs:\n  %s\n  %s\n", i,
                   QJsonDocument(app::toolToJson(got[i])).toJson(QJsonDocument::Compact).constData(),
                   QJsonDocument(app::toolToJson(expected[i])).toJson(QJsonDocument::Compact).constData());
  brokenPromise(what);
}

}  // namespace mx::fuzz
