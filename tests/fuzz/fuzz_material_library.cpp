// Fuzz target of the materials library (parseMaterialLibrary: resources/materials.json, or a shop's
// own file given by `materials --library`). Refusals are InputError only. Accepted entries have finite
// values, unique ids, and each one's copy in a project (materialSpecOf) passes the project rules and
// reads back from the project file unchanged; the library written back (materialLibraryJson) reads
// back to the same entries and writes the same text again.
#include <QByteArray>
#include <QJsonObject>
#include <QSet>
#include <cstdint>
#include <cstdio>

#include "document/project.h"
#include "document/project_validation.h"
#include "fuzz_check.h"
#include "services/material_library.h"
#include "services/material_library_json.h"
#include "services/service_errors.h"

namespace {

using mx::fuzz::require;
using mx::fuzz::requireFinite;

void requireFiniteEntry(const mx::app::MaterialEntry& e) {
  requireFinite(e.Kt_N_mm2, "an accepted K_t is finite");
  requireFinite(e.Kr, "an accepted K_r is finite");
  for (const auto& v : {e.Kte_N_mm, e.Kre_N_mm, e.Ka_N_mm2, e.Kae_N_mm, e.process_damping_N_per_m, e.kc11_N_mm2, e.mc})
    if (v) requireFinite(*v, "an accepted optional value is finite");
}

// The entry's copy as the material of a project: valid, and the same after the project file's writer
// and parser.
void checkProjectCopy(const mx::app::MaterialEntry& e) {
  mx::app::Project project;
  project.name = QStringLiteral("fuzz");
  project.material = mx::app::materialSpecOf(e);
  try {
    mx::app::validateProject(project);
    const mx::app::Project reread = mx::app::projectFromJson(mx::app::projectToJson(project));
    require(reread.material == project.material, "the entry's copy reads back from the project file unchanged");
  } catch (const mx::app::ProjectError& error) {
    std::fprintf(stderr, "fuzz: %s\n", error.what());
    mx::fuzz::brokenPromise("the entry's copy is a valid project material");
  }
}

void checkRoundTrip(const std::vector<mx::app::MaterialEntry>& entries) {
  const QByteArray written = mx::app::materialLibraryJson(entries);
  try {
    const std::vector<mx::app::MaterialEntry> again = mx::app::parseMaterialLibrary(written);
    require(again == entries, "the written library reads back to the same entries");
    require(mx::app::materialLibraryJson(again) == written, "the written library writes the same text again");
  } catch (const mx::app::InputError& error) {
    std::fprintf(stderr, "fuzz: %s\n", error.what());
    mx::fuzz::brokenPromise("the written library is refused");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<mx::app::MaterialEntry> entries;
  try {
    entries = mx::app::parseMaterialLibrary(QByteArray(reinterpret_cast<const char*>(data), qsizetype(size)));
  } catch (const mx::app::InputError&) {
    return 0;  // the documented refusal, naming the field, the value and the range
  }
  QSet<QString> ids;
  for (const mx::app::MaterialEntry& e : entries) {
    requireFiniteEntry(e);
    require(!ids.contains(e.id), "the ids of a library are unique");
    ids.insert(e.id);
    checkProjectCopy(e);
  }
  checkRoundTrip(entries);
  return 0;
}
