#pragma once
// Amplitude spectrum plot: |F| [N] against frequency [Hz], with markers at the tooth-passing harmonics
// h f_tp and at the chatter frequency f_c. QCustomPlot stays behind this class.
#include <QString>
#include <QVector>
#include <QWidget>
#include <optional>
#include <span>

class QCustomPlot;
class QCPGraph;
class QCPAbstractItem;

namespace mx::widgets {

struct SpectrumSeries {
  QVector<double> hz, amplitude;
};

class SpectrumPlot : public QWidget {
  Q_OBJECT
 public:
  explicit SpectrumPlot(QWidget* parent = nullptr);

  // Single-sided amplitude spectrum (mx::AmplitudeSpectrum: mean removed, Hann window) for plotting:
  // from 0 to max(5 f_tp, 1.25 x the largest peak away from the tooth-passing harmonics, 1.25 extra_hz),
  // capped at Nyquist, and reduced to at most max_points points by keeping each group's maximum.
  // Empty for fewer than 4 samples or an invalid rate.
  static SpectrumSeries computeSpectrum(std::span<const double> signal, double sample_rate_hz, double tooth_passing_hz,
                                        double extra_hz = 0.0, int max_points = 4000);

  // `label` names the signal in the legend (e.g. "live, last 20 revolutions").
  void setSpectrum(const SpectrumSeries& spectrum, const QString& label);
  void setAmplitudeUnit(const QString& symbol);        // the force unit of the amplitudes given ("N", "lbf")
  void setToothPassingHz(double hz);                   // 0: no harmonic markers
  void setChatterFrequency(std::optional<double> hz);  // nullopt: no chatter marker
  void clear();
  void replotQueued();

  int pointCount() const;
  int harmonicMarkerCount() const { return harmonic_count_; }
  bool chatterMarkerShown() const { return chatter_hz_.has_value(); }

 private:
  void rebuildMarkers();

  QCustomPlot* plot_;
  QCPGraph* amplitude_;
  QCPGraph* harmonic_legend_;  // no data: legend entries of the vertical markers
  QCPGraph* chatter_legend_;
  QVector<QCPAbstractItem*> markers_;
  double tooth_passing_hz_ = 0.0;
  std::optional<double> chatter_hz_;
  double max_hz_ = 0.0;
  int harmonic_count_ = 0;
};

}  // namespace mx::widgets
