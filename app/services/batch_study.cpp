#include "services/batch_study.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>

#include "document/output_file.h"
#include "services/batch_cases.h"
#include "services/batch_manifest_json.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {

QString besideManifest(const QString& manifest_path, const char* suffix) {
  const QFileInfo info(manifest_path);
  return info.dir().filePath(info.completeBaseName() + QLatin1String(suffix));
}

// The material section as the project file writes it.
QJsonObject materialSection(const Project& project, const MaterialSpec& material) {
  Project with = project;
  with.material = material;
  return projectToJson(with).value("material").toObject();
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
  for (const MaterialSpec& m : request.materials) manifest.materials.push_back(materialSection(project, m));
  manifest.options = request.options;
  // Checked as batch reads it, before anything is written.
  const BatchManifest checked = batchManifestFromJson(batchManifestJson(manifest), manifest.folder);
  files.cases = static_cast<qint64>(expandBatchCases(checked, {project}).size());
  saveProject(project, files.project);
  const QByteArray text = QJsonDocument(batchManifestJson(manifest)).toJson(QJsonDocument::Indented);
  if (const QString error = writeFileAtomically(manifest_path, text); !error.isEmpty())
    throw InputError(QString("%1: cannot write the manifest: %2").arg(manifest_path, error));
  return files;
}

}  // namespace mx::app
