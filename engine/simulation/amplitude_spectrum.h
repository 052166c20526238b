#pragma once
// Single-sided amplitude spectrum of a sampled signal (FFTW r2c): mean removed, Hann window, amplitudes
// scaled by the window's coherent gain so that a bin-centred sinusoid A sin(2 pi f t) reads A.
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace mx {

class AmplitudeSpectrum {
 public:
  AmplitudeSpectrum(std::span<const double> signal, double sample_rate_hz);
  // Spectrum of a two-component signal: sqrt(A_a^2 + A_b^2) per bin (same length and rate).
  static AmplitudeSpectrum vectorSum(const AmplitudeSpectrum& a, const AmplitudeSpectrum& b);

  double binHz() const { return bin_hz_; }
  std::size_t bins() const { return amplitude_.size(); }  // N/2 + 1
  const std::vector<double>& amplitude() const { return amplitude_; }
  double frequencyOfBin(std::size_t k) const { return static_cast<double>(k) * bin_hz_; }

  // Largest amplitude among the bins within one bin of f (absorbs a frequency between two bins).
  double amplitudeNear(double frequency_hz) const;

  struct Peak {
    double frequency_hz = 0.0;  // refined by Gaussian interpolation of the three log-amplitudes
    double amplitude = 0.0;     // of the peak bin
  };
  // The largest local maximum (bins 1 .. N/2 - 1) whose frequency is not excluded; nullopt if none.
  std::optional<Peak> largestPeak(const std::function<bool(double)>& excluded) const;

 private:
  AmplitudeSpectrum() = default;
  double bin_hz_ = 0.0;
  std::vector<double> amplitude_;
};

}  // namespace mx
