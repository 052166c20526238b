#pragma once
// The content of the expert report, computed from a project: the expert system run with simulation
// (Rules 4-6 of Rubio, De la Sen & Ibeas 2006), the figure 4 sweep at the c3 in use, the lobes of
// the selected tool and the time-domain simulation of q**. Plain data, shared by millexpert-report
// and the GUI's File > Export report; the GUI renders the figures and fills in their image paths.
#include <QDateTime>
#include <QString>
#include <QStringList>
#include <array>
#include <optional>
#include <vector>

#include "document/project.h"
#include "expert/expert_session.h"
#include "simulation/simulation_types.h"

namespace mx::app {

struct ReportSweep {
  double c3 = 0.0;
  std::vector<double> c1;                     // 0, step, ... 1 - c3
  std::vector<std::vector<double>> min_cost;  // [tool][i]; NaN where the tool has no admissible point
};

// Figure 1: nominal and margined ZOA envelopes of the selected tool, and the power limit at q*'s feed.
struct ReportLobes {
  std::vector<double> speed_rpm;
  std::vector<double> nominal_mm;      // NaN where unbounded
  std::vector<double> margined_mm;     // alpha * b_lim at the margin delta
  std::vector<double> power_limit_mm;  // on speed_rpm; empty = none
  QString power_limit_label;
};

struct ReportData {
  Project project;
  QString project_path;
  QStringList tool_ids;  // in project order; ToolChoice::tool indexes it
  ExpertSettings settings;
  CostWeights weights;  // requested (the project's, or --c), before Rule 6
  ExpertResult result;  // result.weights: after Rule 6
  CostNormalisation normalisation;
  ReportSweep sweep;
  ReportLobes lobes;
  std::optional<SimulationTrace> simulation;  // at q**; none without a refinement
  double simulation_revolutions = 0;
  QString simulation_title;
  QString lobe_image;        // Figure 1 (PNG), set by the renderer
  QString simulation_image;  // Figure 2 (PNG); empty when there is no q**
  QString sweep_image;       // Figure 3 (PNG)
  QString version;
  QDateTime generated;

  QString toolId(std::size_t index) const { return tool_ids.value(static_cast<qsizetype>(index)); }
  QString selectedId() const { return toolId(result.ranking.selected().tool); }
};

struct ReportRequest {
  std::optional<std::array<double, 3>> c;  // overrides the project's c (must lie on the simplex)
  double sweep_step = 0.025;
  QString version;
};

// Throws ProjectError (bad project), InputError (c off the simplex), ComputationError (empty
// admissible space, naming the constraint) or mx::InvalidInput.
ReportData computeReportData(const QString& project_path, const ReportRequest& request);

}  // namespace mx::app
