#include "services/batch_cases.h"

#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <algorithm>

#include "services/service_errors.h"

namespace mx::app {

namespace {

qsizetype orOne(std::size_t n) {
  return std::max<qsizetype>(1, static_cast<qsizetype>(n));
}

QStringList toolIds(const Project& project) {
  QStringList ids;
  for (const ToolSpec& t : project.tools) ids.append(t.id);
  return ids;
}

QStringList caseToolIds(const BatchManifest& manifest, const Project& base, const BatchCase& c) {
  if (!c.tool.isEmpty()) return {c.tool};
  return manifest.tools ? *manifest.tools : toolIds(base);
}

// The tools in the order the case names them, and what refers to a tool kept consistent with them.
void keepTools(Project& project, const QStringList& ids) {
  std::vector<ToolSpec> kept;
  for (const QString& id : ids) kept.push_back(*project.findTool(id));
  project.tools = std::move(kept);
  if (project.operating_point && !ids.contains(project.operating_point->tool))
    project.operating_point->tool = ids.front();
  if (project.pareto && project.pareto->tool && !ids.contains(*project.pareto->tool)) project.pareto->tool.reset();
  if (project.expert) {
    std::vector<ChatterReportSpec>& reports = project.expert->reported_chatter;
    reports.erase(std::remove_if(reports.begin(), reports.end(),
                                 [&](const ChatterReportSpec& r) { return !ids.contains(r.tool); }),
                  reports.end());
  }
}

template <class Spec>
void replaceSection(std::optional<Spec>& section, const std::vector<Spec>& list, qsizetype index) {
  if (index >= 0) section = list[static_cast<std::size_t>(index)];
}

}  // namespace

void checkListedTools(const BatchManifest& manifest, const std::vector<Project>& projects) {
  if (!manifest.tools) return;
  for (std::size_t p = 0; p < projects.size(); ++p)
    for (const QString& id : *manifest.tools)
      if (projects[p].findTool(id) == nullptr)
        throw InputError(QString("tools: '%1' is not a tool of projects[%2] = '%3'")
                             .arg(id)
                             .arg(p)
                             .arg(manifest.projects[static_cast<qsizetype>(p)]));
}

qint64 countBatchCases(const BatchManifest& manifest, const std::vector<Project>& projects) {
  double tools = 0.0;  // per-tool computations: the tool level summed over the projects
  for (const Project& p : projects)
    tools += manifest.perTool() ? static_cast<double>(caseToolIds(manifest, p, {}).size()) : 1.0;
  const double count = tools * static_cast<double>(orOne(manifest.machines.size())) *
                       static_cast<double>(orOne(manifest.materials.size())) *
                       static_cast<double>(orOne(manifest.operations.size()));
  if (count > static_cast<double>(kMaxBatchCases))
    throw InputError(QString("the manifest gives %1 cases (projects%2 x machines x materials x operations): at "
                             "most %3; split it into several manifests")
                         .arg(count, 0, 'g', 4)
                         .arg(manifest.perTool() ? " x tools" : "")
                         .arg(kMaxBatchCases));
  return static_cast<qint64>(count);
}

std::vector<BatchCase> expandBatchCases(const BatchManifest& manifest, const std::vector<Project>& projects,
                                        const std::function<bool(qint64)>& keep) {
  std::vector<BatchCase> cases;
  qint64 next = 0;
  const qsizetype machines = orOne(manifest.machines.size()), materials = orOne(manifest.materials.size()),
                  operations = orOne(manifest.operations.size());
  const auto index = [](std::size_t n, qsizetype i) { return n == 0 ? qsizetype{-1} : i; };
  for (std::size_t p = 0; p < projects.size(); ++p) {
    const QStringList tools = manifest.perTool() ? caseToolIds(manifest, projects[p], {}) : QStringList{QString()};
    for (const QString& tool : tools)
      for (qsizetype m = 0; m < machines; ++m)
        for (qsizetype a = 0; a < materials; ++a)
          for (qsizetype o = 0; o < operations; ++o)
            if (const qint64 c = next++; !keep || keep(c))
              cases.push_back({c, static_cast<qsizetype>(p), tool, index(manifest.machines.size(), m),
                               index(manifest.materials.size(), a), index(manifest.operations.size(), o)});
  }
  return cases;
}

Project batchCaseProject(const BatchManifest& manifest, const BatchSections& sections, const Project& base,
                         const BatchCase& c) {
  Project project = base;
  keepTools(project, caseToolIds(manifest, base, c));
  replaceSection(project.machine, sections.machines, c.machine);
  replaceSection(project.material, sections.materials, c.material);
  replaceSection(project.operation, sections.operations, c.operation);
  return project;
}

QJsonValue batchCaseTool(const BatchCase& c, const Project& case_project) {
  if (!c.tool.isEmpty()) return c.tool;
  return QJsonArray::fromStringList(toolIds(case_project));
}

QJsonObject batchCaseInputs(const BatchManifest& manifest, const BatchCase& c, const Project& case_project) {
  return {{"computation", manifest.computation},
          {"options", manifest.options},
          {"project", manifest.projects[c.project]},
          {"tool", batchCaseTool(c, case_project)},
          {"document", projectToJson(case_project)}};
}

QString batchCaseHash(const QJsonObject& inputs) {
  const QByteArray text = QJsonDocument(inputs).toJson(QJsonDocument::Compact);
  return QString::fromLatin1(QCryptographicHash::hash(text, QCryptographicHash::Sha256).toHex());
}

}  // namespace mx::app
