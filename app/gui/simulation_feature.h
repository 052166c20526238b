#pragma once
// The live time-domain simulation of the operating point (the "simulationDock"): a run on the engine
// thread after every release of the point, streamed revolution by revolution into the view; a newer
// run cancels the older one (generation ids). Whatever else moves the point or changes the tool (a
// Pareto pick, the feed, undo, another active tool) greys the shown run as stale at once and re-runs
// once the changes pause; an edit of the cut re-runs at once. A run that cannot start clears the view.
#include <QMainWindow>
#include <QTimer>

#include "feature_context.h"
#include "simulation_data.h"
#include "window_feature.h"

namespace mx::widgets {
class SimulationView;
}

namespace mx::gui {

class SimulationRunner;

class SimulationFeature : public WindowFeature {
  Q_OBJECT
 public:
  SimulationFeature(QMainWindow* window, FeatureContext& context);

  void projectChanged(const app::Project& project, Features recompute) override;
  void projectReplaced() override;
  void stop() override;
  void addViewActions(QMenu* view, QToolBar* toolbar) override;

  // Simulates the operating point of the active tool (nothing without a point or a feed).
  void start();
  SimulationRunner* runner() const { return runner_; }
  widgets::SimulationView* view() const { return view_; }

 signals:
  void simulationShown();  // the summary of the current run is on the view

 private:
  void onFinished(quint64 generation, const SimulationSummary& summary);
  // The shown (or running) run is of the active tool at the current point.
  bool runIsOfCurrentState() const;
  void onPointOrToolChanged();
  void showCannotSimulate(const QString& reason);
  // Replaces the run's raw Smith-Tlusty speed by a point checked on the shown tool's lobes.
  void checkSuggestion(SimulationSummary& summary) const;

  FeatureContext& context_;
  SimulationRunner* runner_;
  widgets::SimulationView* view_;
  quint64 generation_ = 0;
  QString shown_tool_;  // the tool and point of the run on the view
  app::PickedPoint shown_point_;
  QTimer rerun_timer_;  // one run once the point or the tool stops changing
};

}  // namespace mx::gui
