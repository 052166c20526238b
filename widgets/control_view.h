#pragma once
// The adaptive force-control view: tuning beta of the beta-FROH hold and the controller.
//   left:   beta slider and spin box (debounced), "Sweep beta", the run's metrics, the controller
//           settings editor and the workpiece depth-profile editor;
//   centre: the closed loop on a shared time axis (force with the depth of cut, tracking error, feed,
//           parameter estimates);
//   right:  J_c(beta) with the unstable-zero region and the current beta, and the pole-zero map of H_beta:
//           side by side in a wide, short column (the bottom dock at 1080p), else one above the other.
// The centre and right columns scroll vertically rather than squash their plots in a short dock.
// The view never calls the engine: the main window reacts to betaChanged / settingsEdited /
// workpieceEdited / sweepRequested, runs the engine and feeds the results back.
#include <QPointer>
#include <QString>
#include <QVector>
#include <QWidget>

#include "control_data.h"
#include "display_units.h"

class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QScrollArea;
class QSlider;
class QSplitter;

namespace mx::widgets {

class ControlBetaSlider;
class ControlMetricsPanel;
class ControlPlots;
class ControlSettingsEditor;
class DepthProfileEditor;
class JcCurvePlot;
class PoleZeroPlot;

class ControlView : public QWidget {
  Q_OBJECT
 public:
  explicit ControlView(QWidget* parent = nullptr);

  void setBeta(double beta);           // slider [-1, 1] step 0.01 plus a spin box; no signal
  void setUnits(DisplayUnits* units);  // the plots, metrics and settings in shop units; nullptr: metric
  double beta() const;
  int betaGesture() const;  // the beta slider drag that emits betaChanged, 0 outside a drag
  void setTraces(const ControlTraces& t);
  void setMetrics(const ControlMetricsView& m);  // overshoots, settling, J_c, feed range, "unstable zero" warning
  void setJcCurve(const JcCurveView& c);         // curve, current beta, shaded beta < threshold, best beta
  void setPoleZero(const PoleZeroView& pz);
  void setSettings(const ControllerSettingsView& s);  // no signal
  ControllerSettingsView settings() const;
  void setWorkpiece(const QVector<DepthStepView>& steps);  // no signal
  QVector<DepthStepView> workpiece() const;
  void setBusy(bool busy);
  void setStatus(const QString& text);

  // Figures 9-12 style export of the closed loop (force, tracking error, feed) as one PNG; an empty
  // title gives "… β = <beta>". False on failure.
  bool saveResponsePlots(const QString& path, int width = 1600, int height = 1200, const QString& title = {});
  bool saveJcPlot(const QString& path, int width = 1200, int height = 700);

  // Tests.
  // Points of a named graph: "reference", "model", "force sampled", "force continuous", "depth", "error",
  // "feed", "feed continuous", "feed limit", "theta <name>", "Jc", "poles", "zeros"; -1 if unknown.
  int graphPointCount(const QString& graph_name) const;
  QSlider* betaSlider() const;
  QDoubleSpinBox* betaSpin() const;
  QPushButton* sweepButton() const { return sweep_; }
  bool isBusy() const { return busy_; }
  QString statusText() const;
  ControlPlots* plots() const { return plots_; }
  JcCurvePlot* jcPlot() const { return jc_; }
  PoleZeroPlot* poleZeroPlot() const { return pole_zero_; }
  ControlMetricsPanel* metricsPanel() const { return metrics_; }
  ControlSettingsEditor* settingsEditor() const { return settings_; }
  DepthProfileEditor* depthProfileEditor() const { return depth_; }
  QScrollArea* plotsScroll() const { return plots_scroll_; }
  QScrollArea* chartsScroll() const { return charts_scroll_; }
  Qt::Orientation chartsOrientation() const;

 signals:
  void betaChanged(double beta);  // debounced 150 ms after the user moves the slider or spin (at once on release)
  void settingsEdited(const mx::widgets::ControllerSettingsView& s);       // after a valid edit
  void workpieceEdited(const QVector<mx::widgets::DepthStepView>& steps);  // a valid profile
  void sweepRequested();                                                   // "Sweep β"

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  QWidget* buildLeftColumn();
  void arrangeCharts();
  void showBeta(double beta);  // markers and captions follow the slider at once

  ControlBetaSlider* beta_;
  QPushButton* sweep_;
  QProgressBar* busy_bar_;
  QLabel* status_;
  ControlMetricsPanel* metrics_;
  ControlSettingsEditor* settings_;
  DepthProfileEditor* depth_;
  ControlPlots* plots_;
  JcCurvePlot* jc_;
  PoleZeroPlot* pole_zero_;
  QSplitter* charts_;
  QScrollArea* plots_scroll_;
  QScrollArea* charts_scroll_;
  ControlTraces traces_;
  QPointer<DisplayUnits> units_;
  bool busy_ = false;
};

}  // namespace mx::widgets
