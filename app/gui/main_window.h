#pragma once
// MillExpert main window: the project document with undo/redo and autosave, the interactive lobe
// chart (central), docks for the tool library, machine and operation, the operating-point readouts,
// the live simulation, the expert ranking and the Pareto study, and the engine thread behind them.
// Force control, machining and the supervisor are features it hosts (window_feature.h): it hands them
// each project change and applies the edits they request.
#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMainWindow>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>
#include <QToolButton>
#include <utility>
#include <vector>

#include "display_units.h"
#include "document/project_document.h"
#include "engine_runner.h"
#include "expert/expert_session.h"
#include "feature_recompute.h"
#include "lobe_chart_view.h"
#include "operating_point_readout.h"
#include "point_evaluator.h"
#include "services/pareto_study.h"

namespace mx::widgets {
class HistoryView;
class MonitoringPanel;
class OperatorRulesEditor;
class ParetoFrontView;
class ParetoWeightsPanel;
class RequirementsPanel;
struct ParetoPointView;
class RankingTable;
class WeightsPanel;
class ToolLibraryEditor;
class MachineOperationPanel;
class SimulationView;
}  // namespace mx::widgets

namespace mx::gui {

class SimulationRunner;
class ExpertRunner;
class ParetoRunner;
class WindowFeature;
struct RefinementOutcome;
struct SimulationSummary;

// The project's cost weights c, c_r, c_t, c_f (defaults where the project has none).
CostWeights projectWeightsOf(const app::Project& project);
// The project's pareto.weights (equal weights when absent).
ParetoWeights projectParetoWeightsOf(const app::Project& project);

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  enum class RecoveryPolicy { Ask, Recover, Discard };
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  bool openProject(const QString& path);  // false (and a message unless quiet) on a bad file
  bool saveProject(const QString& path = {});
  const app::Project* project() const { return &doc_.project(); }
  app::ProjectDocument* document() { return &doc_; }
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
  // Issue 5: the Pareto expert system, learning database, monitoring and operator rules.
  ParetoRunner* pareto() const { return pareto_; }
  widgets::ParetoWeightsPanel* paretoWeightsPanel() const { return pareto_weights_; }
  widgets::ParetoFrontView* paretoFrontView() const { return front_view_; }
  widgets::RequirementsPanel* requirementsPanel() const { return requirements_; }
  widgets::MonitoringPanel* monitoringPanel() const { return monitoring_; }
  widgets::HistoryView* historyView() const { return history_; }
  widgets::OperatorRulesEditor* rulesEditor() const { return rules_editor_; }
  const std::optional<app::ParetoChoice>& paretoChoice() const { return pareto_choice_; }
  QString learningDatabasePath() const;  // default: LearningDatabase::defaultPath()
  void setLearningDatabasePath(const QString& path);
  void recordOperatingPoint();                   // Rule 14, source operator or automatic
  void moveToParetoChoice();                     // the operating point := the Pareto choice (undoable)
  void reportChatter(double chatter_hz);         // Module VI: Rule 16 speed, re-selection, record, simulate
  void setQuiet(bool quiet) { quiet_ = quiet; }  // no modal dialogs (tests, scripts)
  void setRecoveryPolicy(RecoveryPolicy policy) { recovery_ = policy; }
  void setMethod(LobeMethod method);
  void startSimulation();
  void setActiveTool(const QString& id);  // the tool of the readouts, shading and markers  // time-domain simulation of
                                          // the current point on the engine thread

 signals:
  void lobesShown();
  void rankingShown();     // the ranking table was refreshed (after a weight change or a new session)
  void refinementShown();  // q** (Rules 5-6) arrived
  void simulationFinished();
  void paretoShown();   // the Pareto choice was recomputed (study ready, weights or requirement changed)
  void historyShown();  // the history view was refreshed from the database

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
  // main_window_pareto.cpp
  void buildParetoDocks();
  void rebuildPareto();
  void onParetoReady(const QString& error);
  std::optional<app::ParetoChoice> chooseWith(const ParetoWeights& w, bool auto_weights);
  void showParetoChoice(const ParetoWeights& w);
  void commitParetoWeights(const ParetoWeights& w, const QString& description,
                           const std::optional<ParetoPoint>& target = std::nullopt);
  void onFrontPointActivated(const widgets::ParetoPointView& point);
  void onRequirementChanged();
  void onAutoWeights();
  // main_window_monitoring.cpp
  std::optional<ParetoPoint> currentParetoPoint() const;
  void refreshHistory();
  void onRulesEdited(const QStringList& rules);
  void updateFiredRules();
  void updateMonitoring(const SimulationSummary* summary = nullptr);
  // main_window.cpp
  void addFeature(WindowFeature* feature);
  void applyFeatureEdit(const WindowFeature* feature, const app::Project& edited, const QString& description,
                        int gesture);
  void onProjectChanged(app::ProjectChanges changes);
  void refreshEditors();
  void recomputeEngine();  // the pending lobes and expert session, once the edits pause
  void recomputeLobes();
  void onLobesReady(const mx::gui::LobeJobResult& result);
  void onPointChanged(const app::PickedPoint& point);
  void onPointDragged(double speed_rpm, double depth_mm);
  void onPointReleased(double speed_rpm, double depth_mm);
  void onSimulationFinished(quint64 generation, const SimulationSummary& summary);
  void updatePowerLimit();
  void showError(const QString& title, const QString& message);

  app::ProjectDocument doc_;
  widgets::DisplayUnits units_;
  widgets::LobeChartView* chart_;
  widgets::OperatingPointReadout* readout_;
  widgets::ToolLibraryEditor* tool_editor_ = nullptr;
  widgets::MachineOperationPanel* machine_panel_ = nullptr;
  widgets::SimulationView* sim_view_ = nullptr;
  widgets::WeightsPanel* weights_panel_ = nullptr;
  widgets::RankingTable* ranking_table_ = nullptr;
  ExpertRunner* expert_ = nullptr;
  ParetoRunner* pareto_ = nullptr;
  widgets::ParetoWeightsPanel* pareto_weights_ = nullptr;
  widgets::RequirementsPanel* requirements_ = nullptr;
  widgets::ParetoFrontView* front_view_ = nullptr;
  widgets::MonitoringPanel* monitoring_ = nullptr;
  widgets::HistoryView* history_ = nullptr;
  widgets::OperatorRulesEditor* rules_editor_ = nullptr;
  QPushButton* record_button_ = nullptr;
  QPushButton* report_chatter_ = nullptr;
  QDoubleSpinBox* chatter_hz_ = nullptr;
  std::optional<app::ParetoChoice> pareto_choice_;
  std::optional<double> last_summary_eta_;
  QString learning_db_path_;
  QTimer pareto_timer_;
  std::vector<WindowFeature*> features_;  // in the order they recompute after a project change
  // The last feature gesture (one slider drag) and the document gesture its edits merge into.
  std::pair<const WindowFeature*, int> feature_gesture_{nullptr, 0};
  int document_gesture_ = 0;
  CostWeights weights_;
  std::optional<Ranking> ranking_;
  std::optional<ExpertResult> refinement_;
  bool show_cost_map_ = false, show_grid_ = false;
  Features pending_engine_;  // Lobes and ExpertSession waiting for recompute_timer_
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
