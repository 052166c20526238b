#pragma once
// The one place that decides which feature of the main window recomputes after a project change.
// Each feature lists the sections its inputs come from (the request builders in app/services and
// app/document/lobe_inputs), so that an edit re-runs exactly the views it can affect.
#include <QFlags>

#include "document/project_changes.h"

namespace mx::gui {

enum class Feature : unsigned {
  Editors = 1u << 0,        // tool table, machine and operation panel, tool choices
  Lobes = 1u << 1,          // the stability lobes of every tool
  Simulation = 1u << 2,     // the time-domain simulation of the operating point
  ExpertSession = 1u << 3,  // a new expert session (lobes and grids of every tool), ranked and refined
  ExpertRerank = 1u << 4,   // Rules 4-6 again from the cached session (new cost weights)
  ParetoStudy = 1u << 5,    // a new Pareto study, then its choice
  ParetoChoice = 1u << 6,   // the choice of the current study for new Pareto weights
  ControlSweep = 1u << 7,   // the J_c(beta) sweep
  ControlRun = 1u << 8,     // the closed loop at the project's beta
  SurfaceFinish = 1u << 9,  // the SDNRP panel's settings
  PartProgram = 1u << 10,   // the override of the opened part program
  Supervisor = 1u << 11,    // the supervisor's scenario and chart, and a shown run
  FiredRules = 1u << 12,    // Rule 18 at the operating point
  TapTest = 1u << 13,       // the active tool's tap-test FRFs in the tap-test view
};
Q_DECLARE_FLAGS(Features, Feature)
Q_DECLARE_OPERATORS_FOR_FLAGS(Features)

Features featuresToRecompute(app::ProjectChanges changes);

}  // namespace mx::gui
