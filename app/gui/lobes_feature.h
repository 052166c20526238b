#pragma once
// The stability-lobe chart (the window's central widget) and the operating point: the lobes of every
// tool on the engine thread once the edits pause, the live readouts (power, MRR, b_lim, ROS) while the
// point is dragged, the power-limit curve, the active tool and the stability method, and the engine's
// progress in the status bar.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMainWindow>
#include <QProgressBar>
#include <QTimer>
#include <QToolButton>
#include <memory>
#include <optional>

#include "engine_runner.h"
#include "feature_context.h"
#include "lobe_chart_view.h"
#include "lobe_job.h"
#include "operating_point_readout.h"
#include "point_evaluator.h"
#include "point_runner.h"
#include "window_feature.h"

namespace mx::gui {

class LobesFeature : public WindowFeature {
  Q_OBJECT
 public:
  // Sets the chart as the window's central widget and adds the "pointDock".
  LobesFeature(QMainWindow* window, FeatureContext& context, EngineRunner* engine);

  void projectChanged(const app::Project& project, Features recompute) override;
  void stop() override;
  void addFileActions(QMenu* file, QToolBar* toolbar) override;
  void addViewActions(QMenu* view, QToolBar* toolbar) override;

  void setMethod(LobeMethod method);
  widgets::LobeChartView* chart() const { return chart_; }
  widgets::OperatingPointReadout* readout() const { return readout_; }
  QString methodAdviceText() const { return method_advice_->isHidden() ? QString() : method_advice_->text(); }
  const std::shared_ptr<const LobeSnapshot>& snapshot() const { return snapshot_; }  // null before the first lobes
  // The readouts show the answer to the latest request (the current point, tool and lobes).
  bool readoutIsCurrent() const { return shown_generation_ == point_runner_->latestGeneration(); }

 signals:
  void lobesShown();       // new lobes are on the chart
  void readoutShown();     // the readouts and the verdict of the current point are shown
  void cancelRequested();  // the Cancel button: every feature stops its engine-thread work

 private:
  QWidget* buildPointPanel();
  void buildStatusBar(QMainWindow* window);
  void connectSignals();
  void refreshToolChoices(const app::Project& project);
  void recompute();
  void onLobesReady(const LobeJobResult& result);
  void setSnapGrid(int tool);
  void showNoTools();
  void pickInitialPoint(int tool);
  void lowerInitialPoint(const PointJobResult& result);  // below the power limit, once its curve is known
  void updateForceLimits();
  void showPoint(const app::PickedPoint& point);  // the marker at once; the readouts from the readout thread
  void requestReadout(const app::PickedPoint& point);
  void onPointEvaluated(const PointJobResult& result);
  void showVerdict(const widgets::PointReadout& r);
  void showStatusPoint();  // the status bar's point and verdict, in shop units
  void showActiveTool();
  void showModelLabel();    // the chart's title: the active tool's stability model
  void showMethodAdvice();  // where the ZOA is approximate for the active tool
  void onPointDragged(double speed_rpm, double depth_mm);

  FeatureContext& context_;
  EngineRunner* engine_;
  widgets::LobeChartView* chart_;
  widgets::OperatingPointReadout* readout_;
  QComboBox* tool_combo_;
  QComboBox* method_combo_;
  QLabel* method_advice_;  // "ZOA: approximate for this tool (...)"; hidden when the method fits
  QDoubleSpinBox* feed_spin_;
  QLabel* status_point_;
  QLabel* status_engine_;
  QProgressBar* progress_;
  QToolButton* cancel_button_;
  QMenu* tools_menu_ = nullptr;  // View > Tools on the chart (checkable)
  QTimer recompute_timer_;       // one lobe computation per burst of edits
  std::shared_ptr<const LobeSnapshot> snapshot_;
  std::shared_ptr<const PointEvaluator> evaluator_;  // immutable: replaced when the lobes or the limits change
  PointRunner* point_runner_;
  LobeMethod method_ = LobeMethod::ZeroOrder;
  int drag_id_ = 1;
  std::optional<app::PickedPoint> initial_point_;  // picked, waiting for the power-limit curve
  quint64 shown_generation_ = 0;                   // of the readout request whose answer the verdict shows
  widgets::PointVerdict verdict_ = widgets::PointVerdict::Unknown;  // of the last evaluated point
  // What the power-limit curve was last requested for (evaluator, tool, feed per tooth).
  std::shared_ptr<const PointEvaluator> power_limit_evaluator_;
  int power_limit_tool_ = -1;
  double power_limit_feed_ = -1.0;
};

}  // namespace mx::gui
