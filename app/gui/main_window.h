#pragma once
// MillExpert main window: the project document with undo/redo and autosave, the interactive lobe
// chart (central), docks for the tool library, machine and operation, the operating-point readouts
// and the live simulation, and the engine thread behind them. Later issues add docks (weights and
// ranking, control, supervisor) next to these.
#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMainWindow>
#include <QProgressBar>
#include <QTimer>
#include <QToolButton>

#include "display_units.h"
#include "expert/expert_session.h"
#include "engine_runner.h"
#include "lobe_chart_view.h"
#include "operating_point_readout.h"
#include "point_evaluator.h"
#include "project_document.h"

namespace mx::widgets {
class RankingTable;
class WeightsPanel;
class ToolLibraryEditor;
class MachineOperationPanel;
class SimulationView;
}  // namespace mx::widgets

namespace mx::gui {

class SimulationRunner;
class ExpertRunner;
struct RefinementOutcome;
struct SimulationSummary;

// The project's cost weights c, c_r, c_t, c_f (defaults where the project has none).
CostWeights projectWeightsOf(const app::Project& project);

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  enum class RecoveryPolicy { Ask, Recover, Discard };
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  bool openProject(const QString& path);  // false (and a message unless quiet) on a bad file
  bool saveProject(const QString& path = {});
  const app::Project* project() const { return &doc_.project(); }
  ProjectDocument* document() { return &doc_; }
  widgets::DisplayUnits* units() { return &units_; }
  widgets::LobeChartView* lobeChart() const { return chart_; }
  widgets::OperatingPointReadout* readout() const { return readout_; }
  widgets::ToolLibraryEditor* toolEditor() const { return tool_editor_; }
  widgets::SimulationView* simulationView() const { return sim_view_; }
  EngineRunner* engine() const { return engine_; }
  SimulationRunner* simulations() const { return sim_runner_; }
  ExpertRunner* expert() const { return expert_; }
  widgets::WeightsPanel* weightsPanel() const { return weights_panel_; }
  widgets::RankingTable* rankingTable() const { return ranking_table_; }
  const PointEvaluator& evaluator() const { return evaluator_; }
  void setQuiet(bool quiet) { quiet_ = quiet; }                     // no modal dialogs (tests, scripts)
  void setRecoveryPolicy(RecoveryPolicy policy) { recovery_ = policy; }
  void setMethod(LobeMethod method);
  void startSimulation();  // time-domain simulation of the current point on the engine thread

 signals:
  void lobesShown();
  void rankingShown();  // the ranking table was refreshed (after a weight change or a new session)
  void refinementShown();  // q** (Rules 5-6) arrived
  void simulationFinished();

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  // main_window_actions.cpp
  void buildActions();
  void buildDocks();
  void updateRecentMenu();
  void addRecentFile(const QString& path);
  // main_window_file.cpp
  void onNew();
  void onOpen();
  bool onSave();
  bool onSaveAs();
  bool maybeSave();
  void onExportChart();
  void onExportReport();  // runs millexpert-report in a separate process (never blocks the GUI)
  void updateTitle();
  // main_window_expert.cpp
  void buildExpertDocks();
  void rebuildExpert();
  void onExpertSessionReady(const QString& error);
  void rerank(const CostWeights& weights);
  void onRefined(const RefinementOutcome& outcome);
  void commitWeights(const CostWeights& weights);
  void updateExpertOverlays();
  // main_window.cpp
  void onProjectChanged();
  void recomputeLobes();
  void onLobesReady(const mx::gui::LobeJobResult& result);
  void onPointChanged(const PickedPoint& point);
  void onPointDragged(double speed_rpm, double depth_mm);
  void onPointReleased(double speed_rpm, double depth_mm);
  void onSimulationFinished(quint64 generation, const SimulationSummary& summary);
  void setActiveTool(const QString& id);
  void updatePowerLimit();
  void showError(const QString& title, const QString& message);

  ProjectDocument doc_;
  widgets::DisplayUnits units_;
  widgets::LobeChartView* chart_;
  widgets::OperatingPointReadout* readout_;
  widgets::ToolLibraryEditor* tool_editor_ = nullptr;
  widgets::MachineOperationPanel* machine_panel_ = nullptr;
  widgets::SimulationView* sim_view_ = nullptr;
  widgets::WeightsPanel* weights_panel_ = nullptr;
  widgets::RankingTable* ranking_table_ = nullptr;
  ExpertRunner* expert_ = nullptr;
  CostWeights weights_;
  std::optional<Ranking> ranking_;
  std::optional<ExpertResult> refinement_;
  bool show_cost_map_ = false, show_grid_ = false;
  QByteArray engine_inputs_;  // the project minus the cost weights: a change of it needs new lobes
  EngineRunner* engine_;
  SimulationRunner* sim_runner_ = nullptr;
  PointEvaluator evaluator_;
  std::shared_ptr<const LobeSnapshot> snapshot_;
  QComboBox* tool_combo_;
  QComboBox* method_combo_;
  QDoubleSpinBox* feed_spin_;
  QLabel* status_point_;
  QLabel* status_engine_;
  QProgressBar* progress_;
  QToolButton* cancel_button_;
  QMenu* recent_menu_ = nullptr;
  QMenu* tools_menu_ = nullptr;  // View > Tools on the chart (checkable)
  QTimer recompute_timer_;
  QString active_tool_;
  LobeMethod method_ = LobeMethod::ZeroOrder;
  int drag_id_ = 1;
  bool quiet_ = false;
  RecoveryPolicy recovery_ = RecoveryPolicy::Ask;
  quint64 sim_generation_ = 0;
  double power_limit_feed_ = -1.0;  // feed per tooth the power-limit curve was drawn for
};

}  // namespace mx::gui
