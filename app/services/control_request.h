#pragma once
// The project's "control" section (adaptive force control under beta-FROH, 2006 paper,
// section 4) in engine form: shop units in the section (document/process_sections.h, ranges checked
// when the project is loaded), SI in the engine, defaults applied here (docs/project-file.md).
// Requests the project cannot serve throw ProjectError (exit 2) naming the field.
#include <QString>

#include "control/closed_loop.h"
#include "control/force_reference.h"
#include "document/project.h"

namespace mx::app {

struct ControlRequest {
  QString tool;
  AdaptiveControlSettings settings;
  ForceReference reference;  // how F_r was chosen ("project" when given explicitly)
  // control.programme: one workpiece step per programmed point (with its spindle speed), and each point's own
  // programmed feed (m/s) when the project gives it, reported beside the controller's.
  bool programme = false;
  std::vector<std::optional<double>> programmed_feed_m_s;
};

ControlRequest controlRequestFrom(const ControlSection& section, const Project& project);
// The project's control section; ProjectError when it has none.
ControlRequest controlRequestFromProject(const Project& project);

// Back to the section (the GUI's editors write it with it); keys the request does not carry keep
// their value from `previous`.
ControlSection controlSectionFrom(const ControlRequest& request, ControlSection previous);

}  // namespace mx::app
