// The materials library's files (the bundled resource, a shop's file) and the project's copy of an entry.
#include "services/material_library.h"

#include <QFile>
#include <QStringList>

#include "core/invalid_input.h"
#include "document/input_files.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {

// qt_add_resources in app/services/CMakeLists.txt.
constexpr char kBundledLibrary[] = ":/materials/materials.json";

std::vector<MaterialEntry> parseNamed(const QString& name, const QByteArray& bytes) {
  try {
    return parseMaterialLibrary(bytes);
  } catch (const InputError& e) {
    throw InputError(QString("%1: %2").arg(name, QString::fromStdString(e.what())));
  }
}

}  // namespace

std::vector<MaterialEntry> readMaterialLibrary(const QString& path) {
  QByteArray bytes;
  try {
    bytes = readBoundedFile(path, kMaterialLibraryFileLimit);
  } catch (const InvalidInput& e) {
    throw InputError(QString("%1: %2").arg(path, QString::fromStdString(e.what())));
  }
  return parseNamed(path, bytes);
}

std::vector<MaterialEntry> bundledMaterialLibrary() {
  QFile file(kBundledLibrary);
  if (!file.open(QIODevice::ReadOnly))
    throw InputError(QString("%1: the bundled materials library is missing from this build").arg(kBundledLibrary));
  return parseNamed("resources/materials.json", file.readAll());
}

const MaterialEntry& materialById(const std::vector<MaterialEntry>& library, const QString& id) {
  QStringList ids;
  for (const MaterialEntry& e : library) {
    if (e.id == id) return e;
    ids << e.id;
  }
  throw InputError(QString("material \"%1\" is not in the library (its ids: %2)")
                       .arg(id, ids.isEmpty() ? QString("none") : ids.join(", ")));
}

MaterialSpec materialSpecOf(const MaterialEntry& entry) {
  MaterialSpec m;
  m.name = entry.name;
  m.Kt_N_mm2 = entry.Kt_N_mm2;
  m.Kr = entry.Kr;
  m.Kte_N_mm = entry.Kte_N_mm;
  m.Kre_N_mm = entry.Kre_N_mm;
  m.Ka_N_mm2 = entry.Ka_N_mm2;
  m.Kae_N_mm = entry.Kae_N_mm;
  m.process_damping_N_per_m = entry.process_damping_N_per_m;
  m.library = entry.id;
  return m;
}

}  // namespace mx::app
