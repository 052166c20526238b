// Fuzz target of the FreeCAD tool-bit and library readers (services/tool_formats/freecad_library.h).
// The input is read twice: whole, as one .fctb; and as a library, split at lines "%%": the first
// part is the .fctl, each further part a bit file, its first line the name the library's "path" gives
// (an in-memory loader). A refusal is a ToolLibraryError. Accepted tools are finite and valid; their
// export reads back (with no --teeth: the count travels in attribute.MillExpert) to the same tools,
// exactly when the first import gave each tool its own id and bit file, else without ids and origins;
// and an exact round trip exports the same files again.
#include <QByteArray>
#include <QJsonDocument>
#include <QSet>
#include <cstdint>
#include <map>

#include "cam_tool_checks.h"
#include "fuzz_check.h"
#include "services/tool_formats/freecad_library.h"

namespace {

using namespace mx;

const app::ToolImportOptions kTeeth{3};

app::FreeCadBitLoader loaderOf(const std::map<QString, QByteArray>& bits) {
  return [bits](const QString& reference) {
    const auto found = bits.find(reference);
    if (found == bits.end()) throw app::ToolLibraryError(QString("%1: no such bit").arg(reference));
    return found->second;
  };
}

std::map<QString, QByteArray> exportedBits(const app::FreeCadExport& files) {
  std::map<QString, QByteArray> bits;
  for (const auto& [path, bytes] : files.bits) bits[path.mid(path.indexOf('/') + 1)] = bytes;
  return bits;
}

// Each tool has its own id, and a bit file name the export keeps (one file per distinct name).
bool exportKeepsNames(const std::vector<app::ToolSpec>& tools, const app::FreeCadExport& files) {
  QSet<QString> names;
  for (const app::ToolSpec& tool : tools) {
    const QString path = tool.origin->data.value("path").toString();
    if (path.isEmpty()) return false;
    names.insert(path.toLower());
  }
  return fuzz::idsUnique(tools) && static_cast<std::size_t>(names.size()) == files.bits.size();
}

void checkBit(const QByteArray& input) {
  app::ImportedLibrary first;
  try {
    first = app::readFreeCadBit(input, "fuzz.fctb", kTeeth);
  } catch (const app::ToolLibraryError&) {
    return;
  }
  fuzz::require(first.tools.size() + first.skipped.size() == 1, "a bit is one tool or one skipped tool");
  fuzz::requireValidCamTools(first);
  if (first.tools.empty()) return;
  const app::FreeCadExport files = app::writeFreeCadLibrary(first.tools, "fuzz");
  fuzz::require(files.bits.size() == 1 && files.bits[0].first == "Bit/fuzz.fctb", "a lone bit keeps its file name");
  try {
    const app::ImportedLibrary again = app::readFreeCadBit(files.bits[0].second, "fuzz.fctb");
    fuzz::requireSameTools(again.tools, first.tools, "an exported bit reads back to the same tool");
  } catch (const app::ToolLibraryError& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    fuzz::brokenPromise("an exported bit reads back");
  }
}

void checkLibrary(const QByteArray& input) {
  const QList<QByteArray> parts = input.split('\n');
  QByteArray fctl;
  std::map<QString, QByteArray> bits;
  QByteArray* current = &fctl;
  for (const QByteArray& line : parts) {
    if (line == "%%") {
      current = nullptr;
      continue;
    }
    if (!current) {
      current = &bits[QString::fromUtf8(line)];
      continue;
    }
    current->append(line).append('\n');
  }
  app::ImportedLibrary first;
  try {
    first = app::readFreeCadLibrary(fctl, "fuzz.fctl", loaderOf(bits), kTeeth);
  } catch (const app::ToolLibraryError&) {
    return;
  }
  fuzz::requireValidCamTools(first);
  const app::FreeCadExport files = app::writeFreeCadLibrary(first.tools, "fuzz");
  app::ImportedLibrary again;
  try {
    again = app::readFreeCadLibrary(files.library, "fuzz.fctl", loaderOf(exportedBits(files)));
  } catch (const app::ToolLibraryError& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    fuzz::brokenPromise("an exported library reads back");
  }
  fuzz::require(again.skipped.empty(), "an exported library holds milling cutters only");
  if (!exportKeepsNames(first.tools, files)) {
    fuzz::requireSameTools(fuzz::anonymous(again.tools), fuzz::anonymous(first.tools),
                           "an exported library reads back to the same tools, renumbered");
    return;
  }
  fuzz::requireSameTools(again.tools, first.tools, "an exported library reads back to the same tools");
  const app::FreeCadExport twice = app::writeFreeCadLibrary(again.tools, "fuzz");
  fuzz::require(twice.library == files.library && twice.bits == files.bits, "a re-import exports the same files");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const QByteArray input(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
  checkBit(input);
  checkLibrary(input);
  return 0;
}
