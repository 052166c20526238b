#pragma once
// Which dynamics a stability computation uses for one tool, and the measured FRFs it reads:
//   modal     the tool's modes (modes_x, modes_y): every method;
//   measured  the tap-test receptance (frf_x, frf_y) where given, the modes elsewhere: the ZOA only,
//             with delta = 0, since a measured FRF gives G(i omega) and not G(-delta + i omega).
// Semi-discretization, the simulation and a margin delta > 0 use the fitted modes instead, and say so.
#include <QString>
#include <optional>

#include "document/project.h"
#include "model/measured_receptance.h"
#include "model/milling_setup.h"
#include "stability/lobe_computation.h"

namespace mx::app {

// "modal" | "measured"; InputError naming `field` otherwise.
DynamicsSource dynamicsSourceFromName(const QString& field, const QString& name);
QString dynamicsName(DynamicsSource source);

// Modal unless an axis has an FRF and no modes (the measured FRF is then all there is).
DynamicsSource defaultDynamics(const ToolSpec& tool);

struct DynamicsChoice {
  DynamicsSource used = DynamicsSource::Modal;
  QString note;  // why the measured FRF was not used although asked for; empty otherwise
};

// The dynamics for `requested` (defaultDynamics when empty). Throws InputError when measured is asked
// for a tool without an FRF, or when the modes are needed and an axis has only an FRF.
DynamicsChoice chooseDynamics(const ToolSpec& tool, std::optional<DynamicsSource> requested, double delta_per_s,
                              StabilityMethod method);

// Throws InputError when an axis has an FRF and no modes: `purpose` ("semi-discretization", "the
// simulation", ...) needs a state-space model, so the FRF must be fitted first.
void requireFittedModes(const ToolSpec& tool, const QString& purpose);

// The receptance of one FRF reference, read from its file (resolved against project.folder).
// Throws InputError naming the tool, the field and the path: a missing or unreadable file, a bad
// dataset index, a quantity that disagrees with the file, an FRF of another direction.
MeasuredAxis loadMeasuredAxis(const Project& project, const ToolSpec& tool, const QString& field,
                              const FrfRefSpec& ref);

// Project::setupFor, with the tool's FRFs read into measured_x / measured_y when `source` is Measured.
MillingSetup dynamicsSetupFor(const Project& project, const QString& tool_id, DynamicsSource source);

}  // namespace mx::app
