#pragma once
// Shared by `rank` and `weights-sweep`: a project's expert inputs (tools, grid, limits, margins and
// weights) in engine form, and the --c / --cr weight flags. The expert section, its method,
// simulated_points and grid.modal_candidate_speeds included, is typed in document/project.h.
#include <QString>
#include <QStringList>
#include <array>
#include <optional>
#include <vector>

#include "document/project.h"
#include "expert/cost_weights.h"
#include "expert/expert_settings.h"
#include "model/milling_setup.h"
#include "services/measured_dynamics.h"

namespace mx::app {

struct ExpertRequest {
  QStringList tool_ids;
  std::vector<MillingSetup> tools;
  ExpertSettings settings;
  std::vector<double> tool_force_limits_n;  // F_allow per tool (Project::toolForceLimitN), aligned with tools
  CostWeights weights;                      // the project's, validated (exit 2 when off the simplex)
};

// Throws ProjectError (exit 2) for missing sections and weights off the simplex.
ExpertRequest expertRequestFromProject(const Project& project);

// Each tool's lobes on its modes or its tap-test FRF (services/measured_dynamics.h) for `requested`:
// measured where asked for and the tool has an FRF, or where an axis has only an FRF; the FRFs are read
// into request.tools. `simulate`: the time-domain refinement (Rule 5) needs every tool's modes.
// Returns the choice per tool, aligned with request.tools. Throws InputError as chooseDynamics.
std::vector<DynamicsChoice> applyExpertDynamics(const Project& project, ExpertRequest& request,
                                                std::optional<DynamicsSource> requested, bool simulate);

// "--name a,b,c": `count` numbers, non-negative, summing to 1 within 1e-6; InputError otherwise.
std::vector<double> parseWeightList(const QString& flag, const QString& text, std::size_t count);

// "zoa" -> zeroth-order approximation, "sdm" -> semi-discretization; InputError naming `where` otherwise.
StabilityMethod stabilityMethodFromText(const QString& text, const QString& where);

}  // namespace mx::app
