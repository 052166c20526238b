#pragma once
// The supervisor dock (Landers & Ulsoy's supervisory machining control):
//   toolbar: controller (none / SMC I / SMC II), Run, Stop, speed (1x, 5x, 20x, max), the operator's
//            Feed hold (checkable) and Chatter buttons (enabled while running), status;
//   beside the tabs: module L's force time constant tau [ms] and where it restarts at contact
//            (supervisor.model_controller), disabled while running;
//   "Run" tab: the Grafcet chart with its tokens (left, scrolled to follow the active steps) and the
//            timeline of F_Y, power and module activity (right), the run's metrics line below;
//   "Compare" tab: SupervisorComparison and a "Compare none / SMC I / SMC II" button;
//   "Edit chart" tab: GrafcetChartEditor.
// The view never calls the engine: the main window reacts to the signals, injects the operator
// events into the running simulation and feeds the display structs back.
#include <QString>
#include <QStringList>
#include <QWidget>

#include "grafcet_chart_data.h"
#include "supervision_data.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QScrollArea;
class QTabWidget;

namespace mx::widgets {

class GrafcetChartEditor;
class GrafcetChartView;
class SupervisionTimeline;
class SupervisorComparison;

class SupervisorView : public QWidget {
  Q_OBJECT
 public:
  explicit SupervisorView(QWidget* parent = nullptr);

  GrafcetChartView* chartView() const { return chart_; }
  SupervisionTimeline* timeline() const { return timeline_; }
  GrafcetChartEditor* editor() const { return editor_; }
  SupervisorComparison* comparison() const { return comparison_; }

  void setControllers(const QStringList& names);  // e.g. {"none","smc1","smc2"}; combo items
  QString controller() const;
  void setController(const QString& name);  // no signal
  void setRunning(bool running);            // enables Stop and the operator buttons, disables Run
  bool isRunning() const { return running_; }
  void setMetrics(const SupervisionMetricsView& m);
  void setStatus(const QString& text);
  bool feedHoldOn() const;
  double speedFactor() const;  // 1, 5, 20 or 0 (= as fast as possible)
  // Module L's settings as the project gives them (defaults filled in); no signal.
  void setModelController(double time_constant_ms, const QString& reset_feed);
  double timeConstantMs() const;
  QString resetFeed() const;  // "model" or "current"

  // Tests.
  QComboBox* controllerCombo() const { return controller_; }
  QComboBox* speedCombo() const { return speed_; }
  QPushButton* runButton() const { return run_; }
  QPushButton* stopButton() const { return stop_; }
  QPushButton* feedHoldButton() const { return feed_hold_; }
  QPushButton* chatterButton() const { return chatter_; }
  QPushButton* compareButton() const { return compare_; }
  QDoubleSpinBox* timeConstantSpin() const { return time_constant_; }
  QComboBox* resetFeedCombo() const { return reset_feed_; }
  QTabWidget* tabs() const { return tabs_; }
  QString metricsText() const;
  QString statusText() const;

 signals:
  void controllerChanged(const QString& name);
  void runRequested();
  void stopRequested();
  void compareRequested();
  void feedHoldToggled(bool on);  // operator feed hold button (checkable)
  void chatterSignalled();        // operator chatter button
  // A committed change of module L's settings (Enter, focus out or a step; a combo choice).
  void timeConstantEdited(double time_constant_ms);
  void resetFeedEdited(const QString& reset_feed);  // "model" or "current"

 private:
  QWidget* buildToolbar();
  QWidget* buildModelControllerRow();
  void setUpModelController();
  void followTokens();

  QComboBox* controller_;
  QComboBox* speed_;
  QPushButton* run_;
  QPushButton* stop_;
  QPushButton* feed_hold_;
  QPushButton* chatter_;
  QPushButton* compare_;
  QDoubleSpinBox* time_constant_;
  QComboBox* reset_feed_;
  QLabel* status_;
  QLabel* metrics_;
  QTabWidget* tabs_;
  QScrollArea* chart_scroll_;
  GrafcetChartView* chart_;
  SupervisionTimeline* timeline_;
  SupervisorComparison* comparison_;
  GrafcetChartEditor* editor_;
  bool running_ = false;
};

}  // namespace mx::widgets
