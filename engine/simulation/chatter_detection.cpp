#include "simulation/chatter_detection.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "simulation/amplitude_spectrum.h"

namespace mx {

double harmonicBandHz(int harmonic, double fundamental_hz, double bin_hz, const SpindleSpeedVariation& ssv) {
  const double base = std::min(std::max(3.0 * bin_hz, 0.01 * fundamental_hz), 0.25 * fundamental_hz);
  const bool modulated = ssv.amplitude_ratio != 0.0 && ssv.frequency_hz > 0.0;
  return base + (modulated ? std::abs(ssv.amplitude_ratio) * harmonic * fundamental_hz + 2.0 * ssv.frequency_hz : 0.0);
}

ChatterIndicators detectChatter(const WindowSignals& window, const ChatterCriteria& criteria) {
  ChatterIndicators out;
  // eq. 11 (2006) and Rule 15 (Pareto). A zero static force (b = 0) has nothing to amplify: eta = 1.
  out.eta = window.max_static_force_n > 0.0 ? window.max_force_n / window.max_static_force_n : 1.0;
  out.chip_ratio = window.max_static_chip_m > 0.0 ? window.max_chip_m / window.max_static_chip_m : 1.0;
  out.chatter_by_eta = out.eta >= criteria.eta_threshold;
  out.chatter_by_chip_ratio = out.chip_ratio >= criteria.chip_ratio_threshold;
  out.chatter = out.chatter_by_eta || out.chatter_by_chip_ratio;
  out.tooth_passing_hz = criteria.teeth * criteria.nominal_rev_per_s;
  out.peak_force_n = window.max_force_n;
  out.peak_power_w = window.peak_power_w;
  if (window.force_n.size() < 4) return out;

  const AmplitudeSpectrum force(window.force_n, window.sample_rate_hz);
  const double ftp = out.tooth_passing_hz;
  out.a_toothpass = force.amplitudeNear(ftp);
  // A peak belongs to the forced response when it lies within the band of its nearest harmonic h f_0
  // (h = 0 is the mean); everything else is self-excited (chatter) content.
  const double f0 = criteria.forced_at_spindle_harmonics ? criteria.nominal_rev_per_s : ftp;
  auto nearHarmonic = [&](double f) {
    const int h = static_cast<int>(std::lround(f / f0));
    return std::abs(f - h * f0) <= harmonicBandHz(h, f0, force.binHz(), criteria.ssv);
  };
  std::optional<AmplitudeSpectrum::Peak> peak;
  if (window.x_m.size() == window.force_n.size() && window.y_m.size() == window.force_n.size()) {
    const AmplitudeSpectrum vibration = AmplitudeSpectrum::vectorSum(
        AmplitudeSpectrum(window.x_m, window.sample_rate_hz), AmplitudeSpectrum(window.y_m, window.sample_rate_hz));
    peak = vibration.largestPeak(nearHarmonic);
  } else {
    peak = force.largestPeak(nearHarmonic);  // no displacement samples: fall back on the force
  }
  if (peak) {
    out.a_chatter = force.amplitudeNear(peak->frequency_hz);
    out.largest_nonharmonic_hz = peak->frequency_hz;
    if (out.chatter) out.chatter_frequency_hz = peak->frequency_hz;
  }
  return out;
}

}  // namespace mx
