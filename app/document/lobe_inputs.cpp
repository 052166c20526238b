#include "document/lobe_inputs.h"

#include "core/invalid_input.h"

namespace mx::app {

SpeedGrid LobeInputs::grid() const {
  return {rpmToRevPerS(from_rpm), rpmToRevPerS(to_rpm), rpmToRevPerS(step_rpm)};
}

LobeInputs lobeInputsFrom(const Project& project, double step_rpm) {
  LobeInputs in;
  in.step_rpm = step_rpm;
  if (project.expert) {
    in.delta_per_s = project.expert->delta_per_s;
    in.alpha = project.expert->alpha;
    if (project.expert->grid) {
      in.from_rpm = project.expert->grid->speed_from_rpm;
      in.to_rpm = project.expert->grid->speed_to_rpm;
    }
  }
  return in;
}

double gridStepRpm(const Project& project, double fallback) {
  return project.expert && project.expert->grid ? project.expert->grid->speed_step_rpm : fallback;
}

}  // namespace mx::app
