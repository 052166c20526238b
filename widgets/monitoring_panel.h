#pragma once
// Rule 17 monitoring signals of the Pareto expert system (module VII): the measured or simulated
// signals of the running point (peak force and power against the spindle limit, feed velocity, MRR,
// the objectives TOL, SURF and ROS, the chatter indicators eta and chip ratio with the Rule 15
// verdict, the tooth-passing and chatter frequencies) and the identified spectrum peaks.
// A missing or non-finite value shows "–". Numbers are written in the C locale, 4 significant digits,
// in the shop units of setUnits() (force, power, feed rate, MRR; the keys keep their SI-style names).
#include <QHash>
#include <QPointer>
#include <QString>
#include <QVector>
#include <QWidget>
#include <optional>

#include "display_units.h"

class QLabel;
class QTableWidget;

namespace mx::widgets {

// In N, W, W, mm/s and cm³/s (the panel converts them to shop units), then min, µm and the ratios.
struct MonitoringValues {
  std::optional<double> peak_force_n, peak_power_w, power_limit_w, feed_velocity_mm_s, mrr_cm3_s, tol_min, surf_um, ros,
      eta, chip_ratio, tooth_passing_hz, chatter_frequency_hz;
  bool chatter = false;
};

struct MonitoringPeak {
  double frequency_hz = 0;
  double amplitude_n = 0;
  QString kind;
  int harmonic = 0;  // k of k n_t N or k N; 0 (shown "–") for a non-harmonic peak
};

class MonitoringPanel : public QWidget {
  Q_OBJECT
 public:
  static constexpr double kChipRatioThreshold = 1.25;  // Rule 15: chatter when chip ratio >= 1.25

  explicit MonitoringPanel(QWidget* parent = nullptr);

  void setUnits(DisplayUnits* units);                   // labels and values follow it; nullptr: metric
  void setValues(const MonitoringValues& v);            // a missing or non-finite value shows "–"
  void setPeaks(const QVector<MonitoringPeak>& peaks);  // table: Frequency [Hz], Amplitude [force], Kind, Harmonic
  void clear();                                         // every value "–", verdict "–", no peaks

  // The displayed text of a signal by key: "peak_force_n", "peak_power_w", "feed_velocity_mm_s",
  // "mrr_cm3_s", "tol_min", "surf_um", "ros", "eta", "chip_ratio", "tooth_passing_hz",
  // "chatter_frequency_hz", "verdict"; empty for an unknown key.
  QString valueText(const QString& key) const;
  QLabel* valueLabel(const QString& key) const;  // nullptr for an unknown key
  QTableWidget* peakTable() const { return peaks_; }

  // "–" when missing or non-finite, else 4 significant digits in the C locale without exponent for
  // 1e-3 <= |v| < 1e9 ("12345", "1.250", "0.01230").
  static QString formatNumber(std::optional<double> v);

 private:
  void setAlarm(QLabel* label, bool alarm);
  void refreshUnits();

  QPointer<DisplayUnits> units_;
  std::optional<MonitoringValues> shown_values_;
  QVector<MonitoringPeak> shown_peaks_;
  QHash<QString, QLabel*> names_;
  QHash<QString, QLabel*> values_;
  QLabel* verdict_;
  QTableWidget* peaks_;
};

}  // namespace mx::widgets
