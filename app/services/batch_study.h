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
  std::vector<MachineSpec> machines;    // each a case; empty: the project's own machine only
  QJsonObject options;                  // the single command's flags by name
};

struct BatchStudyFiles {
  QString manifest;  // as given
  QString project;   // <manifest stem>.mxproj beside it
  qint64 cases = 0;  // how many lines the results file will hold
};

// Writes both files atomically. Throws InputError naming what is wrong (no tool, a tool the project
// lacks, no material, an invalid machine, an unwritable folder) before anything is written.
BatchStudyFiles writeBatchStudy(const Project& project, const BatchStudyRequest& request, const QString& manifest_path);

// <manifest stem>.jsonl beside the manifest: where a study run from the GUI appends its results.
QString batchStudyResultsPath(const QString& manifest_path);

// A machine another project file describes, for the study's list of machines.
struct MachineOfProject {
  QString file;  // the project file it comes from
  MachineSpec machine;
};

// The machine section of each project file, in order. A file that cannot be read, or has no machine
// section, adds its message to `problems` ("cell-3.mxproj: no machine section") instead.
std::vector<MachineOfProject> machinesOfProjects(const QStringList& files, QStringList* problems);

}  // namespace mx::app
