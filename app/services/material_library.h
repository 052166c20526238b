#pragma once
// The materials library (resources/materials.json, bundled as a Qt resource, or a shop's own file of
// the same format; docs/materials-sources.md): typed entries whose values pass the project's rules for
// the material section, and the copy of an entry that a project keeps as its `material`.
#include <QByteArray>
#include <QMap>
#include <QString>
#include <optional>
#include <vector>

#include "core/input_file.h"
#include "document/project.h"

namespace mx::app {

// Where one value of an entry comes from: a citation (with its url and test conditions), or a note
// such as "typical, source not checked".
struct MaterialSource {
  std::optional<QString> cite;
  std::optional<QString> url;
  std::optional<QString> conditions;
  std::optional<QString> note;
  bool operator==(const MaterialSource&) const = default;
};

// One material of the library. The coefficients are those of MaterialSpec (same keys, units and
// ranges); kc11_N_mm2 and mc are the Kienzle constants the derived values come from, for reference.
struct MaterialEntry {
  QString id;         // unique in its library; a project's material.library names it
  QString name;       // non-empty
  QString iso_group;  // ISO 513 group: P, M, K, N, S or H
  double Kt_N_mm2 = 0.0;
  double Kr = 0.0;
  std::optional<double> Kte_N_mm;
  std::optional<double> Kre_N_mm;
  std::optional<double> Ka_N_mm2;
  std::optional<double> Kae_N_mm;
  std::optional<double> process_damping_N_per_m;
  std::optional<double> kc11_N_mm2;
  std::optional<double> mc;
  QMap<QString, MaterialSource> sources;  // by the key of the value they back
  bool operator==(const MaterialEntry&) const = default;
};

inline constexpr char kMaterialLibraryFormat[] = "millexpert-materials";
inline constexpr int kMaterialLibraryVersion = 1;
// The bundled library has nine entries of a few kB; a shop's library of hundreds stays far below.
inline constexpr InputFileLimit kMaterialLibraryFileLimit{16 * kMegabyte, "a materials library"};

// The entries of a library file's bytes. Throws InputError (exit 2) naming the field path, the value
// and the allowed range: "materials[2].Kte_N_mm = -1: must be in [0, 10000]".
std::vector<MaterialEntry> parseMaterialLibrary(const QByteArray& bytes);
// parseMaterialLibrary of the file at `path` (at most kMaterialLibraryFileLimit); messages start with
// the path.
std::vector<MaterialEntry> readMaterialLibrary(const QString& path);
// The library shipped inside the program (resources/materials.json).
std::vector<MaterialEntry> bundledMaterialLibrary();

// The entry with `id`; throws InputError listing the library's ids when there is none.
const MaterialEntry& materialById(const std::vector<MaterialEntry>& library, const QString& id);
// The project's copy of an entry: its name and coefficients, and `library` = its id.
MaterialSpec materialSpecOf(const MaterialEntry& entry);

}  // namespace mx::app
