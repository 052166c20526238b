// Fuzz target of the tool-library CSV import (ToolLibraryCsv::fromCsv, docs/tool-library-csv.md).
// A refused file reports an error and no tools. An accepted one holds valid tools (tool_checks.h), one
// source line per tool, and survives the export: toCsv reads back to the same tools and the same text.
#include <QByteArray>
#include <cstdint>

#include "fuzz_check.h"
#include "services/tool_formats/tool_library_csv.h"
#include "tool_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using mx::app::ToolLibraryCsv;
  using mx::fuzz::require;
  const auto file = ToolLibraryCsv::fromCsv(QByteArray(reinterpret_cast<const char*>(data), qsizetype(size)));
  if (!file.ok()) {
    require(file.tools.empty() && file.lines.empty(), "a refused file gives no tools");
    return 0;
  }
  require(file.lines.size() == file.tools.size(), "one source line per tool");
  for (std::size_t i = 1; i < file.lines.size(); ++i)
    require(file.lines[i] > file.lines[i - 1], "source lines in file order");
  mx::fuzz::requireValidTools(file.tools);

  const QByteArray csv = ToolLibraryCsv::toCsv(file.tools);
  const auto again = ToolLibraryCsv::fromCsv(csv);
  if (!again.ok()) std::fprintf(stderr, "fuzz: %s\n", qPrintable(again.error));
  require(again.ok(), "the exported CSV is accepted");
  require(again.tools == file.tools, "the exported CSV reads back to the same tools");
  require(ToolLibraryCsv::toCsv(again.tools) == csv, "the exported CSV exports to the same text");
  return 0;
}
