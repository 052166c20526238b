#pragma once
// Which sections of a project an edit changed. The document computes this once per edit (undo and
// redo emit the same flags), and the main window recomputes only the features that depend on them
// (app/gui/feature_recompute.h), instead of comparing serialised projects.
#include <QFlags>

#include "document/project.h"

namespace mx::app {

enum class ProjectSection : unsigned {
  Name = 1u << 0,
  Tools = 1u << 1,
  Machine = 1u << 2,
  Material = 1u << 3,
  Operation = 1u << 4,
  Expert = 1u << 5,         // everything of "expert" but the cost weights
  ExpertWeights = 1u << 6,  // expert.c, cr, ct, cf, reported_chatter (no new session)
  Control = 1u << 7,        // everything of "control" but beta
  ControlBeta = 1u << 8,
  Sdnrp = 1u << 9,
  ForceControl = 1u << 10,
  PartProgram = 1u << 11,
  Supervisor = 1u << 12,
  Pareto = 1u << 13,  // everything of "pareto" but the weights
  ParetoWeights = 1u << 14,
  Rules = 1u << 15,           // operator_rules
  Unknown = 1u << 16,         // the file's keys this build does not know (Project::document)
  OperatingPoint = 1u << 17,  // operating_point: where the project opens (no view recomputes)
};
Q_DECLARE_FLAGS(ProjectChanges, ProjectSection)
Q_DECLARE_OPERATORS_FOR_FLAGS(ProjectChanges)

// Every section: a loaded, new or recovered project.
constexpr ProjectChanges kAllSections = ProjectChanges::fromInt((1u << 18) - 1);

// The sections that differ between `before` and `after`; empty for a no-op edit.
ProjectChanges changedSections(const Project& before, const Project& after);

}  // namespace mx::app
