#pragma once
// The expert system (2006 paper, section 3): the session (lobes and admissible grids of every tool)
// is built on the engine thread once the edits pause; a weight change re-ranks on the GUI thread from
// the session's caches (Rule 4, milliseconds); a committed weight change is an undoable edit and
// re-runs Rules 5-6 (cached simulations) on the engine thread for q**. The chart shows q*, q**, and on
// request the cost heat map and the admissible grid of the active tool. File > Export report writes
// the expert report.
#include <QMainWindow>
#include <QTimer>
#include <optional>

#include "expert/expert_session.h"
#include "feature_context.h"
#include "window_feature.h"

namespace mx::widgets {
class LobeChartView;
class RankingTable;
class WeightsPanel;
}  // namespace mx::widgets

namespace mx::gui {

class ExpertRunner;
struct RefinementOutcome;

// The project's cost weights c, c_r, c_t, c_f (defaults where the project has none).
CostWeights projectWeightsOf(const app::Project& project);
// What a report names as its project file: the document's path, "unsaved", or the path "(with unsaved
// changes)"; never the temporary snapshot the report is computed from.
QString reportProjectName(const app::ProjectDocument& document);

class ExpertFeature : public WindowFeature {
  Q_OBJECT
 public:
  // Adds the "weightsDock" (tabbed with the point) and the "rankingDock" (tabbed with the simulation).
  ExpertFeature(QMainWindow* window, FeatureContext& context, widgets::LobeChartView* chart);

  void projectChanged(const app::Project& project, Features recompute) override;
  void projectReplaced() override { opening_ = true; }
  void addFileActions(QMenu* file, QToolBar* toolbar) override;
  void addViewActions(QMenu* view, QToolBar* toolbar) override;

  ExpertRunner* runner() const { return runner_; }
  const CostWeights& weights() const { return weights_; }
  void reportChatter(double chatter_hz);  // Rule 6 evidence at the operating point (undoable)
  // Writes the expert report of the open project to `path` (.html or .pdf) in a separate process;
  // reportWritten or errorRaised follows.
  void exportReportTo(const QString& path);
  void setReportProgram(const QString& program) { report_program_ = program; }  // default: beside the GUI

 signals:
  void rankingShown();     // the ranking table was refreshed (a weight change or a new session)
  void refinementShown();  // q** (Rules 5-6) arrived
  void reportWritten(const QString& path);

 private:
  void buildDocks(QMainWindow* window);
  void rebuild();
  void onSessionReady(const QString& error);
  void rerank(const CostWeights& weights);
  void onRefined(const RefinementOutcome& outcome);
  std::vector<ChatterReport> reportedChatter() const;
  void commitWeights(const CostWeights& weights);
  void updateOverlays();
  void placeDefaultPoint();
  void drawSessionOverlays(int tool);
  void exportReport();

  FeatureContext& context_;
  widgets::LobeChartView* chart_;
  ExpertRunner* runner_;
  widgets::WeightsPanel* weights_panel_;
  widgets::RankingTable* ranking_table_;
  QTimer rebuild_timer_;  // one session per burst of edits
  CostWeights weights_;
  std::optional<Ranking> ranking_;
  std::optional<ExpertResult> refinement_;
  bool opening_ = false;  // a project was opened and its first session is not refined yet: q* places the point
  bool show_cost_map_ = false;
  bool show_grid_ = false;
  QString report_program_;
};

}  // namespace mx::gui
