#include "expert/response_metrics.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "simulation/amplitude_spectrum.h"

namespace mx {

ResponseMetrics responseMetrics(const MillingSetup& setup, const OperatingPoint& point, const SimulationResult& result,
                                int evaluated_revolutions) {
  ResponseMetrics m;
  m.a_chatter = result.indicators.a_chatter;
  m.chatter = result.indicators.chatter || result.diverged;
  const SimulationTrace& trace = result.trace;
  if (trace.size() < 8) return m;
  const double tooth_period = point.toothPeriodS(setup.teeth);

  // Per-tooth-period peaks of |F| from t = 0.
  std::vector<double> peaks;
  for (std::size_t i = 0; i < trace.size(); ++i) {
    const auto k = static_cast<std::size_t>(std::floor(trace.time_s[i] / tooth_period + 1e-9));
    if (k >= peaks.size()) peaks.resize(k + 1, 0.0);
    peaks[k] = std::max(peaks[k], trace.force_n[i]);
  }
  if (peaks.size() > 1) peaks.pop_back();  // the last period may be incomplete
  const std::size_t last = std::min<std::size_t>(peaks.size(), static_cast<std::size_t>(setup.teeth));
  double final_value = 0.0;
  for (std::size_t k = peaks.size() - last; k < peaks.size(); ++k) final_value += peaks[k];
  final_value /= static_cast<double>(last);
  if (final_value > 0.0) {
    const double top = *std::max_element(peaks.begin(), peaks.end());
    m.overshoot = std::max(0.0, top / final_value - 1.0);
    for (std::size_t k = peaks.size(); k-- > 0;) {
      if (std::abs(peaks[k] - final_value) > 0.05 * final_value) {
        m.settling_time_s = static_cast<double>(k + 1) * tooth_period;
        break;
      }
    }
  }

  // Resultant-force spectrum over the evaluated window.
  const double t_end = trace.time_s.back();
  const double t_from = t_end - evaluated_revolutions / point.spindle_rev_per_s;
  const auto first = static_cast<std::size_t>(std::lower_bound(trace.time_s.begin(), trace.time_s.end(), t_from) -
                                              trace.time_s.begin());
  if (trace.size() - first < 8 || !(result.dt_s > 0.0)) return m;
  const AmplitudeSpectrum spectrum(std::span<const double>(trace.force_n).subspan(first), 1.0 / result.dt_s);
  const double ftp = setup.teeth * point.spindle_rev_per_s;
  const double nyquist = 0.5 / result.dt_s;
  const double a1 = spectrum.amplitudeNear(ftp);
  const double a2 = spectrum.amplitudeNear(2.0 * ftp);
  for (int h = 1; h <= 50 && h * ftp < nyquist - spectrum.binHz(); ++h)
    m.a_toothpass_max = std::max(m.a_toothpass_max, spectrum.amplitudeNear(h * ftp));
  if (a1 > 0.0) {
    m.r12h = a2 / a1;
    m.r1ch = m.a_chatter / a1;
  }
  return m;
}

}  // namespace mx
