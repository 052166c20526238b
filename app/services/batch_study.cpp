#include "services/batch_study.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>

#include "document/output_file.h"
#include "services/batch_cases.h"
#include "services/batch_manifest_json.h"
#include "services/batch_sections.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {

QString besideManifest(const QString& manifest_path, const char* suffix) {
  const QFileInfo info(manifest_path);
  return info.dir().filePath(info.completeBaseName() + QLatin1String(suffix));
}

// A section (the material, the machine) as the project file writes it: the project's own writer, so
// that a manifest section carries exactly the keys and units of a project's.
template <class Spec>
QJsonObject sectionOf(const Project& project, std::optional<Spec> Project::*section, const Spec& value,
                      const char* key) {
  Project with = project;
  with.*section = value;
  return projectToJson(with).value(QLatin1String(key)).toObject();
}

void checkRequest(const Project& project, const BatchStudyRequest& request) {
  if (request.tools.isEmpty()) throw InputError("batch study: no tool is checked; check at least one");
  for (const QString& tool : request.tools)
    if (project.findTool(tool) == nullptr)
      throw InputError(QString("batch study: tool '%1' is not in the project").arg(tool));
  if (request.materials.empty()) throw InputError("batch study: no material is checked; check at least one");
}

}  // namespace

QString batchStudyResultsPath(const QString& manifest_path) {
  return besideManifest(manifest_path, ".jsonl");
}

BatchStudyFiles writeBatchStudy(const Project& project, const BatchStudyRequest& request,
                                const QString& manifest_path) {
  checkRequest(project, request);
  BatchStudyFiles files{manifest_path, besideManifest(manifest_path, ".mxproj"), 0};
  BatchManifest manifest;
  manifest.computation = request.computation;
  manifest.folder = QFileInfo(manifest_path).absolutePath();
  manifest.projects = {QFileInfo(files.project).fileName()};
  manifest.tools = request.tools;
  for (const MaterialSpec& m : request.materials)
    manifest.materials.push_back(sectionOf(project, &Project::material, m, "material"));
  for (const MachineSpec& m : request.machines)
    manifest.machines.push_back(sectionOf(project, &Project::machine, m, "machine"));
  manifest.options = request.options;
  // Checked as batch reads it, before anything is written.
  const BatchManifest checked = batchManifestFromJson(batchManifestJson(manifest), manifest.folder);
  readBatchSections(checked);  // each machine, material and operation by the project file's rules
  files.cases = static_cast<qint64>(expandBatchCases(checked, {project}).size());
  saveProject(project, files.project);
  const QByteArray text = QJsonDocument(batchManifestJson(manifest)).toJson(QJsonDocument::Indented);
  if (const QString error = writeFileAtomically(manifest_path, text); !error.isEmpty())
    throw InputError(QString("%1: cannot write the manifest: %2").arg(manifest_path, error));
  return files;
}

std::vector<MachineOfProject> machinesOfProjects(const QStringList& files, QStringList* problems) {
  std::vector<MachineOfProject> machines;
  for (const QString& file : files) {
    try {
      const Project p = loadProject(file);
      if (p.machine)
        machines.push_back({file, *p.machine});
      else
        problems->append(QString("%1: no machine section").arg(file));
    } catch (const std::exception& e) {
      problems->append(QString::fromStdString(e.what()));
    }
  }
  return machines;
}

}  // namespace mx::app
