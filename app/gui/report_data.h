#pragma once
// The content of the expert report, collected from a project: the expert system run with simulation
// (Rules 4-6 of Rubio, De la Sen & Ibeas 2006), the figure 4 sweep at the c3 in use, the time-domain
// simulation of q** and the three figures rendered offscreen as PNG files. Plain data: the builder
// (ReportBuilder) and the writer (ReportWriter) only read it.
#include <QDateTime>
#include <QString>
#include <QStringList>
#include <array>
#include <optional>
#include <vector>

#include "expert/expert_session.h"
#include "project/project.h"

namespace mx::gui {

struct ReportSweep {
  double c3 = 0.0;
  std::vector<double> c1;                    // 0, step, ... 1 - c3
  std::vector<std::vector<double>> min_cost;  // [tool][i]; NaN where the tool has no admissible point
};

struct ReportData {
  app::Project project;
  QString project_path;
  QStringList tool_ids;               // in project order; ToolChoice::tool indexes it
  ExpertSettings settings;
  CostWeights weights;                // requested (the project's, or --c), before Rule 6
  ExpertResult result;                // result.weights: after Rule 6
  CostNormalisation normalisation;
  ReportSweep sweep;
  QString lobe_image;                 // Figure 1 (PNG)
  QString simulation_image;           // Figure 2 (PNG); empty when there is no q**
  QString sweep_image;                // Figure 3 (PNG)
  double simulation_revolutions = 0;  // of Figure 2
  QString version;
  QDateTime generated;

  QString toolId(std::size_t index) const { return tool_ids.value(static_cast<qsizetype>(index)); }
  QString selectedId() const { return toolId(result.ranking.selected().tool); }
};

struct ReportOptions {
  std::optional<std::array<double, 3>> c;  // overrides the project's c (must lie on the simplex)
  QString image_dir;                        // existing directory for the figures
  double sweep_step = 0.025;
  int image_width = 1200;
  int image_height = 675;
};

// Throws app::ProjectError (bad project), app::CliError (code 2: weights off the simplex; code 1: empty
// admissible space, naming the constraint), mx::InvalidInput, or std::runtime_error when a figure
// cannot be written. Needs a QApplication for the figures.
ReportData collectReportData(const QString& project_path, const ReportOptions& options);

}  // namespace mx::gui
