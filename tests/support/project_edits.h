#pragma once
// Test helper: copies of a project with one field changed, as the views request them.
#include "document/project.h"

namespace mx::test {

// `project` with control.beta := beta (the project must have a control section).
inline app::Project withBeta(const app::Project& project, double beta) {
  app::Project edited = project;
  edited.control->beta = beta;
  return edited;
}

}  // namespace mx::test
