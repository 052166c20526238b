#pragma once
// A batch study of the open project, as File > Batch study writes it: the manifest (the fixed
// interface of docs/shop-scale.md) and, beside it, a snapshot of the project it names, so that the
// study reruns the same inputs on this machine or a cluster whatever happens to the open project.
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <vector>

#include "document/project.h"

namespace mx::app {

struct BatchStudyRequest {
  QString computation;                  // lobes, rank, pareto or point
  QStringList tools;                    // of the project; at least one
  std::vector<MaterialSpec> materials;  // each a case; at least one
  QJsonObject options;                  // the single command's flags by name
};

struct BatchStudyFiles {
  QString manifest;  // as given
  QString project;   // <manifest stem>.mxproj beside it
  qint64 cases = 0;  // how many lines the results file will hold
};

// Writes both files atomically. Throws InputError naming what is wrong (no tool, a tool the project
// lacks, no material, an unwritable folder) before anything is written.
BatchStudyFiles writeBatchStudy(const Project& project, const BatchStudyRequest& request, const QString& manifest_path);

// <manifest stem>.jsonl beside the manifest: where a study run from the GUI appends its results.
QString batchStudyResultsPath(const QString& manifest_path);

}  // namespace mx::app
