#pragma once
// The machines, materials and operations of a batch manifest as typed project sections, checked by the
// project file's own rules so that a manifest accepts exactly what a project accepts.
#include <vector>

#include "document/project.h"
#include "services/batch_manifest.h"

namespace mx::app {

struct BatchSections {
  std::vector<MachineSpec> machines;
  std::vector<MaterialSpec> materials;
  std::vector<OperationSpec> operations;
};

// Throws InputError naming the manifest field ("machines[1].spindle_power_W = -5: must be in ..."),
// also for a key the project section does not know.
BatchSections readBatchSections(const BatchManifest& manifest);

}  // namespace mx::app
