#pragma once
// Live simulation view: streams a running time-domain simulation chunk by chunk.
//   (1) tool displacement x, y [um] (left axis) and resultant force |F| [N] (right axis) against time,
//   (2) spindle power P [W] against time with the spindle power limit,
//   (3) the force amplitude spectrum with the tooth-passing harmonics and the chatter frequency,
// and the indicators eta and chip-thickness ratio against their thresholds, the verdict and a one-click
// "Move to N rpm" for the Smith-Tlusty speed. Memory is bounded: each signal keeps the last
// capacity() samples in a ring buffer; plots repaint at most ~30 Hz (rpQueuedReplot). A time trace with
// more samples in view than twice the plot's pixel columns is drawn as its min/max envelope per tooth
// period, or per pixel column when that is longer (TraceGraph), redrawn at each layout (zoom, pan,
// resize). The legends sit under the plots. Force and power are shown
// in the shop units of setUnits() (the data comes in N and W). QCustomPlot stays behind this class.
#include <QColor>
#include <QElapsedTimer>
#include <QPointer>
#include <QString>
#include <QWidget>
#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "display_units.h"
#include "ring_buffer.h"
#include "simulation_data.h"

class QCustomPlot;
class QCPGraph;
class QLabel;
class QPushButton;
class QTimer;

namespace mx::widgets {

class IndicatorGauge;
class SpectrumPlot;
class TraceGraph;

class SimulationView : public QWidget {
  Q_OBJECT
 public:
  static constexpr std::size_t kDefaultCapacity = 20000;
  static constexpr int kReplotIntervalMs = 33;
  enum class Trace { X, Y, Force, Power };

  explicit SimulationView(QWidget* parent = nullptr, std::size_t capacity = kDefaultCapacity);
  ~SimulationView() override;

  void setUnits(DisplayUnits* units);  // nullptr: metric
  // A new run: clears the plots and indicators. spindle_power_limit_w <= 0: no limit line.
  void beginRun(double spindle_power_limit_w, int teeth, double tooth_passing_hz);
  void appendChunk(const mx::gui::SimulationChunkData& chunk);
  void setSummary(const mx::gui::SimulationSummary& summary);
  // A failed or cancelled run: keeps the traces, shows the message.
  void setStatus(const QString& message);
  // The shown run no longer matches the operating point, the tool or the project: the traces stay,
  // greyed, the status says why, and the verdict and the suggested speed are withdrawn until a new run.
  void setStale(const QString& reason);
  bool isStale() const { return stale_; }
  QString statusText() const;
  void clear();

  // Test accessors.
  std::size_t capacity() const { return time_.capacity(); }
  int sampleCount() const { return static_cast<int>(time_.size()); }           // samples kept per signal
  int plottedSampleCount() const { return static_cast<int>(plot_t_.size()); }  // samples the plots were given
  // What a time trace draws (after the plot's next layout): envelope or raw, its points and extremes.
  bool envelopeShown(Trace trace) const;
  int drawnPointCount(Trace trace) const;
  std::pair<double, double> drawnValueRange(Trace trace) const;
  int plotColumns(Trace trace) const;      // pixel columns of the trace's axis rect at its last drawing
  int envelopeBuckets(Trace trace) const;  // min/max pairs of its last envelope
  QColor traceColor(Trace trace) const;
  QColor axisLabelColor(Trace trace) const;  // of the trace's value axis
  void setTimeRange(double t0, double t1);   // zooms both time plots
  int spectrumPointCount() const;
  double latestTime() const { return time_.empty() ? 0.0 : time_.back(); }
  bool chatterShown() const { return chatter_shown_; }
  QString verdictText() const;
  QString suggestedSpeedText() const;  // empty when no speed is suggested
  double suggestedSpeedRpm() const { return suggested_rpm_; }
  QString suggestionNote() const;
  bool replotPending() const;
  int flushCount() const { return flush_count_; }  // plot updates so far (coalesced chunks)

 signals:
  // The suggested point: depth_mm is NaN when the depth stays.
  void moveToPointRequested(double speed_rpm, double depth_mm);

 private:
  void scheduleReplot();
  void flushPlots();
  void relabel();
  void showSummaryValues(const mx::gui::SimulationSummary& s);
  void updateLiveSpectrum();
  void updatePowerLimit();
  void drawTraces(QCustomPlot* plot);
  const TraceGraph& trace(Trace trace) const;
  QWidget* buildIndicatorPanel();

  QPointer<DisplayUnits> units_;
  std::optional<mx::gui::SimulationSummary> summary_;
  RingBuffer<double> time_, x_um_, y_um_, force_n_, power_w_;
  QCustomPlot* motion_plot_;
  QCustomPlot* power_plot_;
  SpectrumPlot* spectrum_;
  std::unique_ptr<TraceGraph> force_trace_, x_trace_, y_trace_, power_trace_;
  QCPGraph* limit_graph_ = nullptr;
  // The kept samples as the plots draw them (time [s], displacements [um], force and power in shop units).
  std::vector<double> plot_t_, plot_x_, plot_y_, plot_force_, plot_power_;
  IndicatorGauge* eta_gauge_ = nullptr;
  IndicatorGauge* chip_gauge_ = nullptr;
  QLabel* status_label_ = nullptr;
  QLabel* verdict_label_ = nullptr;
  QLabel* details_label_ = nullptr;
  QPushButton* move_button_ = nullptr;
  QLabel* suggestion_label_ = nullptr;
  QTimer* replot_timer_;
  QElapsedTimer spectrum_clock_;

  double power_limit_w_ = 0.0;
  double tooth_passing_hz_ = 0.0;
  int teeth_ = 0;
  void setPlotsGreyed(bool greyed);

  bool running_ = false;
  bool stale_ = false;
  bool summary_shown_ = false;
  bool chatter_shown_ = false;
  double suggested_rpm_ = 0.0;
  double suggested_depth_mm_ = 0.0;  // NaN: the depth stays
  int flush_count_ = 0;
};

}  // namespace mx::widgets
