// Fuzz target of the tool-library JSON import (ToolLibraryCsv::fromJson over toolsFromJson): a bare
// array of tools or an object with "tools". A refused file reports an error and no tools. Accepted
// tools are valid (tool_checks.h), and their export (toJson, a minimal project) reads back, as a
// library and as a project, to the same tools and the same text.
#include <QByteArray>
#include <QJsonDocument>
#include <cstdint>

#include "fuzz_check.h"
#include "services/tool_formats/tool_library_csv.h"
#include "tool_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using mx::app::ToolLibraryCsv;
  using mx::fuzz::require;
  const auto file = ToolLibraryCsv::fromJson(QByteArray(reinterpret_cast<const char*>(data), qsizetype(size)));
  if (!file.ok()) {
    require(file.tools.empty(), "a refused file gives no tools");
    return 0;
  }
  mx::fuzz::requireValidTools(file.tools);

  const QByteArray json = ToolLibraryCsv::toJson(file.tools);
  const auto again = ToolLibraryCsv::fromJson(json);
  if (!again.ok()) std::fprintf(stderr, "fuzz: %s\n", qPrintable(again.error));
  require(again.ok() && again.tools == file.tools, "the exported library reads back to the same tools");
  require(ToolLibraryCsv::toJson(again.tools) == json, "the exported library exports to the same text");
  try {
    const auto project = mx::app::projectFromJson(QJsonDocument::fromJson(json).object());
    require(project.tools == file.tools, "the exported library loads as a project with the same tools");
  } catch (const mx::app::ProjectError& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    mx::fuzz::brokenPromise("the exported library loads as a project");
  }
  return 0;
}
