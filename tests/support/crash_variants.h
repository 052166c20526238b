#pragma once
// The two contents the crash-safety writers alternate between (tests/document/document_writer_main.cpp):
// variant k % 2 of a project. They differ in length and in fields near the start and the end of the
// file, so that no torn mix of the two can equal either.
#include "document/project.h"

namespace mx::test {

inline app::Project crashVariant(app::Project project, long long k) {
  const bool b = k % 2 != 0;
  project.name = b ? "Crash safety, variant B (the longer name)" : "Crash safety A";
  if (project.machine) project.machine->spindle_power_W = b ? 7100.0 : 6900.0;
  if (!project.tools.empty()) project.tools.back().helix_deg = b ? 31.0 : 29.0;
  return project;
}

}  // namespace mx::test
