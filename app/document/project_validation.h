#pragma once
// Range and cross-field rules of a Project (also for projects edited in memory, e.g. by the GUI).
#include <optional>

#include "document/project.h"

namespace mx::app {

// Throws ProjectError naming the field path, the value and the allowed range, e.g.
// "tools[1].modes_x[0].damping_pct = 150: must be in (0, 100)". projectFromJson calls it.
void validateProject(const Project& project);
// validateProject as text: "" when valid, else the ProjectError message.
QString projectValidationError(const Project& project);
// The tools' own rules, unique ids, and each radial depth in (0, D] (the operation's, if given).
void validateTools(const std::vector<ToolSpec>& tools, const std::optional<OperationSpec>& operation);

// The radial depth of cut of one tool [mm]: tool.radial_depth_mm, else operation.radial_depth_mm,
// else operation.radial_immersion * D. nullopt when neither the tool nor an operation gives one.
std::optional<double> radialDepthMm(const Project& project, const ToolSpec& tool);

}  // namespace mx::app
