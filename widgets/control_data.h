#pragma once
// Display data of the adaptive force-control view: closed-loop traces, metrics, the J_c(beta)
// curve, the pole-zero map of H_beta, the controller settings and the workpiece depth profile.
// Display units (N, mm, mm/s, s, ms); the main window converts from the engine's SI results.
#include <QMetaType>
#include <QStringList>
#include <QVector>
#include <complex>
#include <optional>

namespace mx::widgets {

struct ControlTraces {                                                        // display units
  QVector<double> t_s;                                                        // sample instants
  QVector<double> reference_n, model_n, force_sampled_n, error_n, feed_mm_s;  // per sample
  QVector<QVector<double>> theta;                                             // theta[k] = estimates at sample k
  QStringList theta_names;                                                    // e.g. "a1","a2","b0","b1"
  QVector<double> dense_t_s, dense_force_n, dense_feed_mm_s;                  // continuous plant output between samples
  QVector<double> depth_t_s, depth_mm;                                        // depth of cut seen by the tool over time
  QVector<double> change_t_s;  // the tool enters the next programmed point (N, b) or depth step
};

struct ControlMetricsView {
  QVector<double> overshoot_pct;  // per depth step (undershoot for a downward step)
  double settling_time_s = 0, jc_n_s = 0, max_force_n = 0, min_feed_mm_s = 0, max_feed_mm_s = 0;
  bool unstable_zero = false;
};

struct JcCurveView {
  QVector<double> beta, jc_n_s;
  std::optional<double> best_beta;
  double threshold_beta = -1.0;  // a zero of H_beta leaves the unit circle for beta < threshold_beta
};

struct PoleZeroView {
  QVector<std::complex<double>> poles, zeros;
};

struct ControllerSettingsView {
  double lambda = 1.0, p0 = 1e5, theta0 = 0.2;
  int reset = 1;  // 0 none, 1 a-priori error > fraction * F_r, 2 trace outside [min, max]
  double reset_fraction = 0.05;
  double xi = 0.75, tr_periods = 4.0;  // reference model damping, rise time in spindle periods
  double tau_c_ms = 0.0;               // 0: default (half a tooth period)
  double feed_max_mm_s = 30.0;
  double force_reference_n = 1200.0;
  bool operator==(const ControllerSettingsView&) const = default;
};

struct DepthStepView {
  double length_mm = 0, depth_mm = 0;
  bool operator==(const DepthStepView&) const = default;
};

}  // namespace mx::widgets

Q_DECLARE_METATYPE(mx::widgets::ControllerSettingsView)
Q_DECLARE_METATYPE(mx::widgets::DepthStepView)
