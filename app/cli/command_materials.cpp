// millexpert-cli materials [--library FILE]
//   {"library": "bundled" or FILE, "materials": [{"id", "name", "iso_group", "Kt_N_mm2", "Kr", the optional
//   "Kte_N_mm", "Kre_N_mm", "Ka_N_mm2", "Kae_N_mm", "process_damping_N_per_m", "kc11_N_mm2", "mc",
//   "sources": {key: {"cite", "url", "conditions"} or {"note"}}}]}
// millexpert-cli materials --apply ID --into PROJECT [--library FILE]
//   {"applied": ID, "project": PROJECT, "material": the project's new material section}
// The library is the bundled resources/materials.json unless --library names a shop's own file of the same
// format. --apply copies the entry into the project's material section (with "library": ID) and saves the
// project atomically; the other sections stay as they were. Exit 2: a bad library file (the message names
// materials[i].field, the value and the range), an unknown id, a bad project or flag.
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "document/project.h"
#include "document/project_validation.h"
#include "document/shortened_text.h"
#include "services/material_library.h"
#include "services/material_library_json.h"

namespace mx::app {

namespace {

int listMaterials(const std::vector<MaterialEntry>& library, const QString& libraryName) {
  printJson({{"library", libraryName}, {"materials", materialEntriesJson(library)}});
  return kExitOk;
}

int applyMaterial(const std::vector<MaterialEntry>& library, const QString& id, const QString& projectPath) {
  const MaterialEntry& entry = materialById(library, id);
  Project project = loadProject(projectPath);
  project.material = materialSpecOf(entry);
  validateProject(project);  // a tool's override may still rule out the new material
  saveProject(project, projectPath);
  printJson({{"applied", id}, {"project", projectPath}, {"material", projectToJson(project).value("material")}});
  return kExitOk;
}

}  // namespace

int runMaterialsCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "List the materials library, or copy one of its entries into a project's material section "
      "(docs/materials-sources.md).");
  parser.addHelpOption();
  parser.addOptions({
      {"library",
       "A materials library of one's own (format millexpert-materials, at most 16 MB) instead of the "
       "bundled one.",
       "FILE"},
      {"apply", "Copy the entry with this id into the project given by --into.", "ID"},
      {"into", "The .mxproj project whose material section --apply replaces (saved atomically).", "PROJECT"},
  });
  parseArguments(parser, arguments);
  if (!parser.positionalArguments().isEmpty())
    throw CliError(QString("materials takes no positional argument, got %1 (the project goes after --into)")
                       .arg(quoted(parser.positionalArguments().front())),
                   kExitBadInput);
  if (parser.isSet("apply") != parser.isSet("into"))
    throw CliError(
        QString("--%1 needs --%2")
            .arg(parser.isSet("apply") ? "apply" : "into", parser.isSet("apply") ? "into PROJECT" : "apply ID"),
        kExitBadInput);
  const bool own = parser.isSet("library");
  const std::vector<MaterialEntry> library =
      own ? readMaterialLibrary(parser.value("library")) : bundledMaterialLibrary();
  if (parser.isSet("apply")) return applyMaterial(library, parser.value("apply"), parser.value("into"));
  return listMaterials(library, own ? parser.value("library") : QString("bundled"));
}

}  // namespace mx::app
