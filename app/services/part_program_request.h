#pragma once
// Part-program overrides from the project, shared by `millexpert-cli override` and the GUI's
// part-program panel. Sections (typed in document/process_sections.h, checked when the project is
// loaded; shop units; every key optional unless noted):
//   "part_program": {
//     "stock_top_mm": 0,              depth = stock top - lowest Z of a feed move (when no profile)
//     "depth_profile": [{"length_mm": 5.87, "depth_mm": 2}, ...],   along the feed path (wins over Z)
//     "speed_rpm": 2134,              the expert system's spindle speed (every S becomes it)
//     "keep_plunge_feed": true,       pure -Z feed moves keep their programmed feed
//     "controller": "adaptive" | "model-based"   default: adaptive when the project has "control"
//   }
//   "force_control": {                the model-based controller (Landers & Ulsoy, F = K d^b f^a)
//     "tool": "T1",                   teeth; default the first tool
//     "model": {"K_N": 760, "depth_exponent": 0.65, "feed_exponent": 0.63},   d, f in mm
//     "reference_force_N": 400,       required for the model-based controller
//     "max_feed_mm_s": 36,            default machine.max_feed_mm_s, else 36
//     "max_feed_per_tooth_mm": 0.6    default operation.max_feed_per_tooth_mm
//   }
// The adaptive controller uses the project's "control" section (control_request.h) and runs along the
// program's cutting blocks (engine/machining/adaptive_path_feeds.h).
#include <QString>
#include <optional>

#include "control/model_based_force_controller.h"
#include "document/project.h"
#include "gcode/gcode_program.h"
#include "machining/part_program_override.h"
#include "services/control_request.h"

namespace mx::app {

struct OverrideRequest {
  PartProgramOverrideSettings settings;
  bool adaptive = false;
  std::optional<ControlRequest> control;         // adaptive
  std::optional<ModelBasedForceSettings> model;  // model-based
  QString controllerName() const;
};

ModelBasedForceSettings modelBasedSettingsFrom(const ForceControlSection& section, const Project& project);
// controller: "adaptive", "model-based" or empty (the project's choice); InputError for another
// --controller, ProjectError for what the project lacks.
OverrideRequest overrideRequestFrom(const PartProgramSection& section, const Project& project,
                                    const QString& controller = {}, std::optional<double> speed_rpm = std::nullopt);
// The project's part_program section (the defaults when it has none).
OverrideRequest overrideRequestFromProject(const Project& project, const QString& controller = {},
                                           std::optional<double> speed_rpm = std::nullopt);

struct OverrideOutcome {
  PartProgramOverrideResult result;
  QString controller;
  std::optional<ClosedLoopMetrics> adaptive_metrics;  // the closed loop along the path (adaptive)
};

// Throws InvalidInput (bad program for this controller) and what the engine throws.
OverrideOutcome runOverride(const OverrideRequest& request, const GcodeProgram& program, const JobControl& job = {});

}  // namespace mx::app
