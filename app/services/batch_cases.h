#pragma once
// The cases of a batch manifest (docs/shop-scale.md): one project x machine x material x operation,
// and also x tool for the per-tool computations (lobes, point), numbered from 0 in the order projects,
// tools, machines, materials, operations. Each case's inputs hash to a SHA-256 that identifies its
// result across reruns, shards and merged files.
#include <QJsonObject>
#include <QString>
#include <functional>
#include <vector>

#include "document/project.h"
#include "services/batch_manifest.h"
#include "services/batch_sections.h"

namespace mx::app {

struct BatchCase {
  qint64 index = 0;
  qsizetype project = 0;
  QString tool;            // per-tool computations: the case's tool; else empty (the case's tools)
  qsizetype machine = -1;  // index into the manifest's list; -1: the project's own section
  qsizetype material = -1;
  qsizetype operation = -1;
};

// A manifest gives at most this many cases: their loop and a shard's list stay bounded.
inline constexpr qint64 kMaxBatchCases = 100000000;

// Throws InputError naming the first listed tool that a project lacks.
void checkListedTools(const BatchManifest& manifest, const std::vector<Project>& projects);
// The number of cases; throws InputError naming the product and kMaxBatchCases above it.
qint64 countBatchCases(const BatchManifest& manifest, const std::vector<Project>& projects);
// The cases that `keep` (default: all) selects by index, in case order.
std::vector<BatchCase> expandBatchCases(const BatchManifest& manifest, const std::vector<Project>& projects,
                                        const std::function<bool(qint64)>& keep = {});

// The project a case computes: the base with the manifest's sections in place of its own, and only
// the case's tools (operating_point, pareto.tool and expert.reported_chatter follow them).
Project batchCaseProject(const BatchManifest& manifest, const BatchSections& sections, const Project& base,
                         const BatchCase& c);
// {"computation", "options", "project" (the path as written), "tool", "document" (the case's project)}.
QJsonObject batchCaseInputs(const BatchManifest& manifest, const BatchCase& c, const Project& case_project);
// The case's tool: its id for a per-tool computation, else the array of the ids it runs together.
QJsonValue batchCaseTool(const BatchCase& c, const Project& case_project);
// SHA-256 (hex) of the inputs as compact JSON with sorted keys (QJsonObject keeps its keys sorted).
QString batchCaseHash(const QJsonObject& inputs);

}  // namespace mx::app
