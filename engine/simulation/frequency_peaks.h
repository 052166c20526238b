#pragma once
// Rule 17 (Pareto paper, module VII, monitoring signals): the frequencies present in a force or
// vibration spectrum, identified so that the operator can deal with them (Wiercigroch & Budak 2001):
//   - ToothPassing: a multiple of the tooth-passing frequency n_t N (forced vibration of the cut);
//   - Spindle: a multiple of the spindle frequency N that is not a tooth-passing multiple (run-out,
//     unequal teeth);
//   - NonHarmonic: anything else (regenerative chatter near a structural mode, or mode coupling).
// A peak is a local maximum of the amplitude spectrum above `relative_floor` times the largest
// amplitude; it is matched to a harmonic when it lies within `tolerance_bins` frequency bins of it.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace mx {

enum class PeakKind { ToothPassing, Spindle, NonHarmonic };

struct FrequencyPeak {
  double frequency_hz = 0.0;
  double amplitude = 0.0;
  PeakKind kind = PeakKind::NonHarmonic;
  int harmonic = 0;  // k of k n_t N or k N; 0 for NonHarmonic
};

struct PeakSettings {
  std::size_t max_peaks = 6;
  double relative_floor = 0.05;  // peaks below this fraction of the largest amplitude are ignored
  double tolerance_bins = 1.5;
};

// The largest peaks, by decreasing amplitude (the DC bin is skipped). Throws InvalidInput when the
// spans differ in length, the frequencies are not increasing, or spindle_hz <= 0 or teeth < 1.
std::vector<FrequencyPeak> identifyPeaks(std::span<const double> frequency_hz, std::span<const double> amplitude,
                                         double spindle_hz, int teeth, const PeakSettings& settings = {});

std::string describe(PeakKind kind);  // "tooth passing (forced)", "spindle (run-out)", "non-harmonic (chatter)"

}  // namespace mx
