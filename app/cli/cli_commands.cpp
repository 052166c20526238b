#include "cli/cli_commands.h"

#include <array>

namespace mx::app {

const CliCommand* findCommand(const QString& name) {
  static const CliCommand commands[] = {
      {"check", "validate a project file", &runCheckCommand},
      {"lobes", "stability lobes of one tool", &runLobesCommand},
      {"simulate", "time-domain simulation of one cutting point", &runSimulateCommand},
      {"point", "stability margin, power and MRR of one operating point", &runPointCommand},
      {"rank", "expert system: rank the tools, select q* and q**", &runRankCommand},
      {"weights-sweep", "minimum tool cost against the weights (figures 4, 5)", &runWeightsSweepCommand},
      {"history", "Rule 14 learning database: programmed points, newest first", &runHistoryCommand},
      {"pareto", "Pareto expert system: TOL, MRR, SURF, ROS objective and non-dominated set", &runParetoCommand},
      {"control", "Adaptive force control under beta-FROH: closed loop over the workpiece, or a beta sweep",
       &runControlCommand},
      {"sdnrp", "Cus & Zuperl surface-roughness control loop (SDNRP)", &runSdnrpCommand},
      {"supervise", "supervisory machining control of a face-milling operation (none, SMC I, SMC II)",
       &runSuperviseCommand},
      {"override", "optimise the feeds of a G-code program with a force controller", &runOverrideCommand},
      {"frf-info", "the FRF datasets of a tap-test file (UFF 58/58b, CSV)", &runFrfInfoCommand},
      {"frf-fit", "modes fitted to one FRF of a tap-test file (LSCF or peak picking)", &runFrfFitCommand},
      {"frf-export", "a tool's FRF from its modes or tap test, written as UFF 58/58b or CSV", &runFrfExportCommand},
      {"library-import", "append the tools of a Fusion 360, FreeCAD, LinuxCNC, CSV or JSON tool library to a project",
       &runLibraryImportCommand},
      {"library-export", "write a project's tools as a Fusion 360, FreeCAD, LinuxCNC, CSV or JSON tool library",
       &runLibraryExportCommand},
      {"coefficients", "cutting coefficients (K_tc, K_rc, K_ac, edge) from test cuts, average-force method",
       &runCoefficientsCommand},
      {"materials", "list the materials library, or copy an entry into a project's material section",
       &runMaterialsCommand},
      {"batch", "one computation over the cases of a manifest (projects x tools x machines x materials x operations)",
       &runBatchCommand},
      {"batch-merge", "one table from batch results files: per machine x material x operation", &runBatchMergeCommand},
  };
  for (const CliCommand& c : commands)
    if (name == QLatin1String(c.name)) return &c;
  return nullptr;
}

}  // namespace mx::app
