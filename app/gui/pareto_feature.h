#pragma once
// The Pareto expert system beside the chart (Rubio et al., Pareto paper, modules V-VII):
// - the ParetoStudy of the project's pareto.tool is built on the engine thread when its inputs change;
//   moving the Pareto weights re-selects on the GUI thread (one pass over the table);
// - committing weights (sliders, the Rule 11 requirement, Rule 12 automatic weights, a history entry,
//   a click on the front) is one undoable step: the pareto.weights edit and the move of the operating
//   point to the selected q;
// - Rule 14: the point can be recorded in the learning database, whose history view queries it;
// - Rule 16: chatter reported at the machine re-selects near the Smith-Tlusty speed;
// - Rule 17: the monitoring dock shows the signals of the point and of its last simulation;
// - Rule 18: the operator-rules editor edits operator_rules; the rules that fire for the active tool
//   are highlighted, with the constraints the point violates.
#include <QDoubleSpinBox>
#include <QMainWindow>
#include <QPushButton>
#include <QTimer>
#include <optional>
#include <set>

#include "feature_context.h"
#include "services/pareto_study.h"
#include "window_feature.h"

namespace mx::widgets {
class HistoryView;
class LearningDatabaseDialog;
class LobeChartView;
class MonitoringPanel;
class NoticeStack;
class OperatorRulesEditor;
class ParetoChoiceSummaryPanel;
class ParetoFrontView;
class ParetoWeightsPanel;
class RequirementsPanel;
struct ParetoPointView;
}  // namespace mx::widgets

namespace mx::gui {

class LearningClient;
class ParetoRunner;
struct LearningHistoryResult;

// The project's pareto.weights (equal weights when absent).
ParetoWeights projectParetoWeightsOf(const app::Project& project);

class ParetoFeature : public WindowFeature {
  Q_OBJECT
 public:
  // Adds the Pareto weights and operator-rules docks (right, tabbed with "weightsDock") and the front,
  // monitoring and history docks (bottom, tabbed with "rankingDock").
  ParetoFeature(QMainWindow* window, FeatureContext& context, widgets::LobeChartView* chart);

  void projectChanged(const app::Project& project, Features recompute) override;
  void addSettingsActions(QMenu* settings) override;  // Learning database...

  ParetoRunner* runner() const { return runner_; }
  const std::optional<app::ParetoChoice>& choice() const { return choice_; }
  // The learning database's file path or URL; default: LearningDatabase::configuredOrDefault().
  QString learningDatabasePath() const;
  void setLearningDatabasePath(const QString& path);  // and refreshes the history
  // No record or history query is waiting for the learning thread (tests wait for it).
  bool learningIdle() const;
  // Settings > Learning database...: window-modal; accepting it stores the setting and points the
  // feature at the chosen location. Returns the open dialog (tests).
  widgets::LearningDatabaseDialog* openLearningDatabaseSettings();
  void recordOperatingPoint();            // Rule 14, source operator or automatic
  void moveToChoice();                    // the operating point := the Pareto choice (undoable)
  void reportChatter(double chatter_hz);  // Module VI: Rule 16 speed, re-selection, record, simulate
  // The Report chatter button: Module VI when the Pareto study is active, else the 2006 Rule 6 loop.
  void routeChatterReport(double chatter_hz);

 signals:
  void paretoShown();   // the choice was recomputed (study ready, weights or requirement changed)
  void historyShown();  // the history view shows the database's answer (rows or the error)

 private:
  // pareto_feature.cpp: the study, the selection and its commits.
  QWidget* buildWeightsPanel();
  void buildDocks(QMainWindow* window);
  void connectSignals();
  void rebuild();
  void disable();
  QString missingSections() const;  // "" when the study can run
  void addParetoSection();
  void setControlsEnabled(bool enabled);
  void onStudyReady(const QString& error);
  std::optional<app::ParetoChoice> chooseWith(const ParetoWeights& w, bool auto_weights);
  void showChoice(const ParetoWeights& w);
  void showChoiceMarker();
  void commitWeights(const ParetoWeights& w, const QString& description,
                     const std::optional<ParetoPoint>& target = std::nullopt);
  void onFrontPointActivated(const widgets::ParetoPointView& point);
  void editParetoSetting(const QString& field, const QString& value);
  void onRequirementChanged();
  void onAutoWeights();
  // pareto_feature_learning.cpp: the learning database, monitoring and operator rules.
  std::optional<ParetoPoint> currentParetoPoint() const;
  void recordFeedback(const ParetoPoint& q);  // Rule 16's re-selected point, source feedback
  void refreshHistory();                      // queued to the learning thread; showHistory() or showHistoryError()
  void showHistory(const LearningHistoryResult& result);
  void showHistoryError(const QString& message);
  void connectLearning();
  void onRulesEdited(const QStringList& rules);
  void updateFiredRules();
  // Rule 17: the readouts of the current point, and its simulation only when it is of this very point.
  void updateMonitoring();

  FeatureContext& context_;
  widgets::LobeChartView* chart_;
  ParetoRunner* runner_;
  widgets::ParetoWeightsPanel* weights_panel_;
  widgets::RequirementsPanel* requirements_;
  widgets::ParetoChoiceSummaryPanel* summary_;
  widgets::ParetoFrontView* front_view_;
  widgets::NoticeStack* front_notice_;  // the front, or why there is none
  widgets::MonitoringPanel* monitoring_;
  widgets::HistoryView* history_;
  widgets::OperatorRulesEditor* rules_editor_;
  QPushButton* record_button_;
  QPushButton* report_chatter_;
  QDoubleSpinBox* chatter_hz_;
  QTimer rebuild_timer_;  // one study per burst of edits
  std::optional<app::ParetoChoice> choice_;
  LearningClient* learning_;  // the database on its own thread
  QString learning_db_path_;
  std::set<quint64> feedback_records_;  // Rule 16 records not yet answered: no status of their own
  widgets::LearningDatabaseDialog* learning_dialog_ = nullptr;
};

}  // namespace mx::gui
