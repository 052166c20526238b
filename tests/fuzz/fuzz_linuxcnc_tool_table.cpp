// Fuzz target of the LinuxCNC tool-table reader (services/tool_formats/linuxcnc_tool_table.h). The
// input is a table, then optionally a line "%%" and its side file. A refusal is a ToolLibraryError.
// Accepted tools are finite and valid; the export (table and side file) reads back, with no --teeth,
// to the same tools, exactly when the table gave each tool its own number, else without ids and
// origins; and an exact round trip exports the same bytes again.
#include <QByteArray>
#include <cstdint>
#include <optional>

#include "cam_tool_checks.h"
#include "fuzz_check.h"
#include "services/tool_formats/linuxcnc_tool_table.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mx;
  const QByteArray input(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
  const qsizetype split = input.indexOf("\n%%\n");
  const QByteArray table = split < 0 ? input : input.left(split);
  const std::optional<QByteArray> side = split < 0 ? std::nullopt : std::optional<QByteArray>(input.mid(split + 4));
  app::ImportedLibrary first;
  try {
    first = app::readLinuxCncToolTable(table, "fuzz.tbl", app::ToolImportOptions{3}, side);
  } catch (const app::ToolLibraryError&) {
    return 0;
  }
  fuzz::require(first.skipped.empty(), "a tool table skips no tool");
  fuzz::requireValidCamTools(first);
  const app::LinuxCncExport files = app::writeLinuxCncToolTable(first.tools);
  app::ImportedLibrary again;
  try {
    again = app::readLinuxCncToolTable(files.table, "fuzz.tbl", {}, files.sideFile);
  } catch (const app::ToolLibraryError& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    fuzz::brokenPromise("an exported table reads back");
  }
  if (!fuzz::idsUnique(first.tools)) {
    fuzz::requireSameTools(fuzz::anonymous(again.tools), fuzz::anonymous(first.tools),
                           "an exported table reads back to the same tools, renumbered");
    return 0;
  }
  fuzz::requireSameTools(again.tools, first.tools, "an exported table reads back to the same tools");
  const app::LinuxCncExport twice = app::writeLinuxCncToolTable(again.tools);
  fuzz::require(twice.table == files.table && twice.sideFile == files.sideFile, "a re-import exports the same bytes");
  return 0;
}
