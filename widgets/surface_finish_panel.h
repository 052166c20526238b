#pragma once
// Surface-finish control panel (Cus & Zuperl SDNRP): the desired roughness Ra_d, the
// machine-tool disturbance on or off, the simulated duration and a Run button; live plots of the six
// signals against time t [s]: (1) Ra and Ra with the machine-tool dynamics, with Ra_d dashed; (2) the
// cutting force F and F with its dynamic component, with the reference F_d dashed; (3) the feed f_a;
// (4) the spindle speed n_a; and a summary of the final values of a run. With "Compare with constant
// feed (no SDNRP)" the run without the loop (the paper's Figs 12 and 14: same plant and disturbance,
// feed and speed held at the initial ones) is drawn dashed beside it. The panel does not run the
// engine: the main window does on its thread and feeds samples and the summary here. QCustomPlot stays
// behind this class; plots repaint through rpQueuedReplot.
#include <QHash>
#include <QLabel>
#include <QPointer>
#include <QString>
#include <QVector>
#include <QWidget>
#include <optional>
#include <utility>

#include "display_units.h"

class QCheckBox;
class QCustomPlot;
class QCPGraph;
class QDoubleSpinBox;
class QPushButton;
class QTimer;

namespace mx::widgets {

struct SurfaceFinishSample {  // display units
  double t_s = 0, ra_um = 0, ra_dynamic_um = 0, force_n = 0, force_dynamic_n = 0, feed_mm_min = 0, speed_rpm = 0;
};

struct SurfaceFinishSummary {  // final values of a run
  double ra_desired_um = 0, fd_n = 0, f_final_n = 0, feed_final_mm_min = 0, speed_final_rpm = 0, ra_produced_um = 0;
  bool feed_saturated = false;
};

class SurfaceFinishPanel : public QWidget {
  Q_OBJECT
 public:
  static constexpr double kMinRaUm = 0.25, kMaxRaUm = 2.5;
  static constexpr double kMinDurationS = 1.0, kMaxDurationS = 120.0, kDefaultDurationS = 15.0;
  static constexpr double kDefaultRaUm = 0.8;
  static constexpr int kDebounceMs = 300;

  explicit SurfaceFinishPanel(QWidget* parent = nullptr);

  double desiredRaUm() const;
  void setDesiredRaUm(double ra);  // no signal; clamps to [kMinRaUm, kMaxRaUm]; NaN ignored
  bool disturbanceOn() const;
  void setDisturbanceOn(bool on);  // no signal
  bool compareOn() const;          // also run without SDNRP (default on)
  void setCompareOn(bool on);      // no signal
  double durationS() const;
  void setDurationS(double s);         // no signal; clamps to [1, 120] s, default 15
  void clear();                        // clears plots and summary
  void setUnits(DisplayUnits* units);  // force and feed in shop units (the data: N, mm/min); nullptr: metric

  // Streams samples (non-finite values are skipped per signal); x axis [0, durationS] (widened when
  // a sample lies beyond it).
  void appendSamples(const QVector<SurfaceFinishSample>& samples);
  // Final values; draws F_d dashed on the force plot and Ra_d dashed on the Ra plot.
  void setSummary(const SurfaceFinishSummary& s);
  void setBusy(bool busy);  // shows "running..." and disables Run
  // The run without SDNRP, drawn dashed (measured F and Ra with the machine-tool dynamics, the held feed
  // and speed), with its final F and Ra in the summary; replaces a baseline shown.
  void setBaseline(const QVector<SurfaceFinishSample>& samples, const SurfaceFinishSummary& summary);
  void clearBaseline();

  int sampleCount() const { return sample_count_; }
  int baselineSampleCount() const { return baseline_.size(); }
  // Displayed text by key: "ra_desired_um", "fd_n", "f_final_n", "feed_final_mm_min", "speed_final_rpm",
  // "ra_produced_um", and without SDNRP "ra_baseline_um", "f_baseline_n"; empty for an unknown key.
  QString summaryText(const QString& key) const;
  QDoubleSpinBox* raSpin() const { return ra_spin_; }
  QCheckBox* disturbanceBox() const { return disturbance_box_; }
  QCheckBox* compareBox() const { return compare_box_; }
  QDoubleSpinBox* durationSpin() const { return duration_spin_; }
  QPushButton* runButton() const { return run_button_; }

  // Test accessors. Graph keys: "ra", "ra_dynamic", "ra_desired", "force", "force_dynamic", "fd",
  // "feed", "speed", and without SDNRP "ra_baseline", "force_baseline", "feed_baseline",
  // "speed_baseline"; -1 / empty / Qt::NoPen for an unknown key.
  int graphDataCount(const QString& graph) const;
  QString graphName(const QString& graph) const;
  Qt::PenStyle graphPenStyle(const QString& graph) const;
  // The plot (0 Ra, 1 force, 2 feed, 3 speed) that holds a graph; -1 for an unknown key.
  int graphPlot(const QString& graph) const;
  // The y range shown on plot i.
  double valueAxisUpper(int plot) const;
  // Smallest and largest value of a graph's data; nullopt when it has none or the key is unknown.
  std::optional<std::pair<double, double>> graphValueRange(const QString& graph) const;
  bool graphInLegend(const QString& graph) const;
  QStringList axisLabels() const;  // x and y labels of the four plots
  double timeAxisUpper() const;
  bool warningShown() const { return !warning_label_->isHidden(); }
  QString warningText() const { return warning_label_->text(); }
  QString statusText() const { return status_label_->text(); }
  bool busy() const { return busy_; }

 signals:
  // The Run button, and (debounced kDebounceMs) a user change of Ra, disturbance or duration.
  void runRequested();

 private:
  struct Range {
    double lo = 0.0, hi = 0.0;
    bool any = false;
    void add(double v);
  };
  QWidget* buildControls();
  QWidget* buildSummary();
  QCustomPlot* makePlot(const QString& y_label, const QString& tooltip);
  void userChanged();
  void setReferences(double ra_d, std::optional<double> fd);  // the dashed Ra_d and F_d (nullopt: none) lines
  void updateRanges();
  void replotAll();
  void relabel();
  void reshow();
  void replayShown();
  void showBaselineLegend(bool shown);
  void finishedStatus();

  QDoubleSpinBox* ra_spin_ = nullptr;
  QCheckBox* disturbance_box_ = nullptr;
  QCheckBox* compare_box_ = nullptr;
  QDoubleSpinBox* duration_spin_ = nullptr;
  QPushButton* run_button_ = nullptr;
  QLabel* status_label_ = nullptr;
  QLabel* warning_label_ = nullptr;
  QHash<QString, QLabel*> summary_;
  QHash<QString, QLabel*> summary_names_;
  QPointer<DisplayUnits> units_;
  QVector<SurfaceFinishSample> samples_;  // of the run shown, as given
  std::optional<SurfaceFinishSummary> shown_summary_;
  QVector<SurfaceFinishSample> baseline_;  // the run without SDNRP, as given
  std::optional<SurfaceFinishSummary> baseline_summary_;
  QVector<QCustomPlot*> plots_;
  QHash<QString, QCPGraph*> graphs_;
  QTimer* debounce_;
  Range ranges_[4];  // value ranges of the Ra, force, feed and speed plots (both runs)
  double ra_reference_ = kDefaultRaUm;
  double fd_reference_ = 0.0;
  bool fd_shown_ = false;
  bool summary_shown_ = false;
  double last_t_ = 0.0;
  int sample_count_ = 0;
  bool busy_ = false;
  bool programmatic_ = false;
};

}  // namespace mx::widgets
