#pragma once
// What the simulation job on the engine thread sends to the live simulation view: a copy of each
// revolution's samples while it runs, and the summary (indicators, suggested speed, spectrum) at the
// end. Plain values, SI units; shared by widgets/ (SimulationView) and app/gui/ (SimulationRunner).
#include <QMetaType>
#include <QString>
#include <QVector>
#include <optional>

namespace mx::gui {

// The samples of one spindle revolution (a copy of mx::SimulationChunk; owned, valid anywhere).
struct SimulationChunkData {
  int revolution = 0;         // revolutions completed (1-based)
  int revolutions = 0;        // total revolutions to simulate
  qsizetype first_index = 0;  // index of time_s[0] in the full trace
  QVector<double> time_s, x_m, y_m, force_n, power_w;
};

struct SimulationSummary {
  // Operating point and limits the run used.
  double spindle_rpm = 0.0;
  int teeth = 0;
  double spindle_power_limit_w = 0.0;  // <= 0: no limit
  // Indicators over the evaluated window (mx::ChatterIndicators).
  double eta = 0.0;
  double chip_ratio = 0.0;
  double eta_threshold = 1.3;
  double chip_ratio_threshold = 1.25;
  bool chatter_by_eta = false;
  bool chatter_by_chip_ratio = false;
  bool chatter = false;
  std::optional<double> chatter_frequency_hz;  // present only with chatter
  double tooth_passing_hz = 0.0;
  double a_chatter_n = 0.0;
  double a_toothpass_n = 0.0;
  double peak_force_n = 0.0;
  double peak_power_w = 0.0;
  bool power_limit_exceeded = false;  // peak power > limit (when a limit is set)
  // Smith-Tlusty speed N = 60 f_c / (n_t k) in (0, max speed], nearest the current one; only with chatter.
  std::optional<double> suggested_rpm;
  int suggested_k = 0;
  // Set once the suggestion is checked on the lobes: a shallower depth when no speed is stable at this
  // one, and what the check found (shown under the button).
  std::optional<double> suggested_depth_mm;
  QString suggestion_note;
  // Run.
  int simulated_revolutions = 0;
  int evaluated_revolutions = 0;
  bool diverged = false;
  // Amplitude spectrum of the resultant force |F| over the evaluated window (Hann, mean removed).
  QVector<double> spectrum_hz, spectrum_n;
};

}  // namespace mx::gui

Q_DECLARE_METATYPE(mx::gui::SimulationChunkData)
Q_DECLARE_METATYPE(mx::gui::SimulationSummary)
