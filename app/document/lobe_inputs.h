#pragma once
// The lobe inputs of a project, shared by `millexpert-cli lobes` and the GUI's lobe chart: the
// speed range of the expert grid (else 1000 to 20000 rpm) and the margins delta and alpha.
#include "document/project.h"
#include "stability/lobe_diagram.h"

namespace mx::app {

struct LobeInputs {
  double from_rpm = 1000.0;
  double to_rpm = 20000.0;
  double step_rpm = 100.0;
  double delta_per_s = 0.0;
  double alpha = 1.0;
  SpeedGrid grid() const;  // in rev/s
};

// step_rpm: the speed step. The CLI passes the grid's step (gridStepRpm, 100 rpm without a grid),
// the GUI a fine 10 rpm, since the ZOA is cheap.
LobeInputs lobeInputsFrom(const Project& project, double step_rpm);
// expert.grid.speed_step_rpm, or `fallback` when the project has no grid.
double gridStepRpm(const Project& project, double fallback);

}  // namespace mx::app
