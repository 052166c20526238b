#include "simulation/frequency_peaks.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/invalid_input.h"

namespace mx {

std::vector<FrequencyPeak> identifyPeaks(std::span<const double> f, std::span<const double> a, double spindle_hz,
                                         int teeth, const PeakSettings& settings) {
  if (f.size() != a.size()) throw InvalidInput("identifyPeaks: frequency and amplitude lengths differ");
  if (!(spindle_hz > 0.0) || !std::isfinite(spindle_hz)) {
    std::ostringstream m;
    m << "spindle frequency = " << spindle_hz << " Hz: must be a finite number > 0";
    throw InvalidInput(m.str());
  }
  if (teeth < 1) throw InvalidInput("teeth = " + std::to_string(teeth) + ": must be >= 1");
  for (std::size_t i = 1; i < f.size(); ++i)
    if (!(f[i] > f[i - 1])) throw InvalidInput("identifyPeaks: the frequencies must increase");
  std::vector<FrequencyPeak> peaks;
  if (f.size() < 3) return peaks;
  const double largest = *std::max_element(a.begin() + 1, a.end());
  const double floor = settings.relative_floor * largest;
  const double bin = f[1] - f[0];
  for (std::size_t i = 1; i + 1 < f.size(); ++i) {
    if (!(a[i] > floor) || a[i] < a[i - 1] || a[i] < a[i + 1]) continue;
    if (i > 1 && a[i] == a[i - 1]) continue;  // a flat top counts once
    FrequencyPeak p{f[i], a[i], PeakKind::NonHarmonic, 0};
    const double tooth_hz = spindle_hz * teeth;
    const double kt = std::round(f[i] / tooth_hz), ks = std::round(f[i] / spindle_hz);
    if (kt >= 1 && std::abs(f[i] - kt * tooth_hz) <= settings.tolerance_bins * bin) {
      p.kind = PeakKind::ToothPassing;
      p.harmonic = static_cast<int>(kt);
    } else if (ks >= 1 && std::abs(f[i] - ks * spindle_hz) <= settings.tolerance_bins * bin &&
               spindle_hz > 2.0 * settings.tolerance_bins * bin) {
      p.kind = PeakKind::Spindle;
      p.harmonic = static_cast<int>(ks);
    }
    peaks.push_back(p);
  }
  std::sort(peaks.begin(), peaks.end(),
            [](const FrequencyPeak& x, const FrequencyPeak& y) { return x.amplitude > y.amplitude; });
  if (peaks.size() > settings.max_peaks) peaks.resize(settings.max_peaks);
  return peaks;
}

std::string describe(PeakKind kind) {
  switch (kind) {
    case PeakKind::ToothPassing:
      return "tooth passing (forced)";
    case PeakKind::Spindle:
      return "spindle (run-out)";
    case PeakKind::NonHarmonic:
      break;
  }
  return "non-harmonic (chatter)";
}

}  // namespace mx
