// Fuzz target of the Fusion 360 tool library import (readFusionLibrary): a JSON library, or a `.tools`
// zip archive of one (told by its first bytes). A refused file throws ToolLibraryError, nothing else.
// Accepted tools hold finite numbers and pass the project's rules one by one (ids may repeat inside
// a library: the merge renames them). Their export in both containers reads back to the same tools,
// none skipped, and exports again to the same bytes.
#include <QByteArray>
#include <cstdint>
#include <cstdio>

#include "fuzz_check.h"
#include "services/tool_formats/fusion_library.h"
#include "tool_checks.h"

namespace {

using mx::app::FusionContainer;
using mx::app::ImportedLibrary;
using mx::app::ToolLibraryError;
using mx::fuzz::require;

void requireValidTool(const mx::app::ToolSpec& tool) {
  mx::fuzz::requireFiniteTool(tool);
  try {
    mx::app::validateImportedTool(tool, "fuzz");
  } catch (const ToolLibraryError& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    mx::fuzz::brokenPromise("accepted tools pass the project's rules");
  }
}

void requireRoundTrip(const ImportedLibrary& library, FusionContainer container) {
  const QByteArray exported = mx::app::writeFusionLibrary(library.tools, container);
  ImportedLibrary again;
  try {
    again = mx::app::readFusionLibrary(exported, "exported");
  } catch (const ToolLibraryError& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    mx::fuzz::brokenPromise("the exported library reads back");
  }
  require(again.skipped.empty(), "the export holds milling cutters only");
  require(again.tools == library.tools, "the exported library reads back to the same tools");
  require(mx::app::writeFusionLibrary(again.tools, container) == exported, "the re-import exports the same bytes");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
  ImportedLibrary library;
  try {
    library = mx::app::readFusionLibrary(bytes, "fuzz.tools");
  } catch (const ToolLibraryError&) {
    return 0;
  }
  for (const mx::app::ToolSpec& tool : library.tools) requireValidTool(tool);
  requireRoundTrip(library, FusionContainer::Json);
  requireRoundTrip(library, FusionContainer::Zipped);
  return 0;
}
