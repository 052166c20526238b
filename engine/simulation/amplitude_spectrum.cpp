#include "simulation/amplitude_spectrum.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>
#include <numeric>
#include <stdexcept>

namespace mx {

namespace {

// FFTW's planner is not thread-safe (fftw_execute is): serialise plan creation and destruction.
std::mutex& plannerMutex() {
  static std::mutex mutex;
  return mutex;
}

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

class RealToComplexPlan {
 public:
  explicit RealToComplexPlan(int n)
      : in_(static_cast<double*>(fftw_malloc(sizeof(double) * static_cast<std::size_t>(n)))),
        out_(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * static_cast<std::size_t>(n / 2 + 1)))) {
    if (!in_ || !out_) throw std::bad_alloc();
    std::lock_guard lock(plannerMutex());
    plan_ = fftw_plan_dft_r2c_1d(n, in_.get(), out_.get(), FFTW_ESTIMATE);
    if (!plan_) throw std::runtime_error("FFTW: could not create an r2c plan");
  }
  ~RealToComplexPlan() {
    std::lock_guard lock(plannerMutex());
    fftw_destroy_plan(plan_);
  }
  RealToComplexPlan(const RealToComplexPlan&) = delete;
  RealToComplexPlan& operator=(const RealToComplexPlan&) = delete;

  double* input() { return in_.get(); }
  const fftw_complex* output() const { return out_.get(); }
  void execute() { fftw_execute(plan_); }

 private:
  std::unique_ptr<double, FftwFree> in_;
  std::unique_ptr<fftw_complex, FftwFree> out_;
  fftw_plan plan_ = nullptr;
};

}  // namespace

AmplitudeSpectrum::AmplitudeSpectrum(std::span<const double> signal, double sample_rate_hz) {
  const std::size_t n = signal.size();
  if (n < 4 || !(sample_rate_hz > 0.0))
    throw std::invalid_argument("AmplitudeSpectrum: need >= 4 samples and a rate > 0");
  bin_hz_ = sample_rate_hz / static_cast<double>(n);
  const double mean = std::accumulate(signal.begin(), signal.end(), 0.0) / static_cast<double>(n);

  RealToComplexPlan plan(static_cast<int>(n));
  double* in = plan.input();
  double window_sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    // Periodic Hann window w_i = 0.5 (1 - cos(2 pi i / n)); coherent gain sum(w) = n/2.
    const double w = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n)));
    in[i] = w * (signal[i] - mean);
    window_sum += w;
  }
  plan.execute();
  const fftw_complex* out = plan.output();
  amplitude_.resize(n / 2 + 1);
  for (std::size_t k = 0; k < amplitude_.size(); ++k) {
    const double scale = (k == 0 || 2 * k == n) ? 1.0 : 2.0;  // single-sided
    amplitude_[k] = scale * std::hypot(out[k][0], out[k][1]) / window_sum;
  }
}

AmplitudeSpectrum AmplitudeSpectrum::vectorSum(const AmplitudeSpectrum& a, const AmplitudeSpectrum& b) {
  if (a.amplitude_.size() != b.amplitude_.size() || a.bin_hz_ != b.bin_hz_)
    throw std::invalid_argument("AmplitudeSpectrum::vectorSum: spectra of different length or rate");
  AmplitudeSpectrum sum;
  sum.bin_hz_ = a.bin_hz_;
  sum.amplitude_.resize(a.amplitude_.size());
  for (std::size_t k = 0; k < sum.amplitude_.size(); ++k)
    sum.amplitude_[k] = std::hypot(a.amplitude_[k], b.amplitude_[k]);
  return sum;
}

double AmplitudeSpectrum::amplitudeNear(double frequency_hz) const {
  const auto centre = static_cast<long long>(std::llround(frequency_hz / bin_hz_));
  double best = 0.0;
  for (long long k = centre - 1; k <= centre + 1; ++k)
    if (k >= 0 && k < static_cast<long long>(amplitude_.size()))
      best = std::max(best, amplitude_[static_cast<std::size_t>(k)]);
  return best;
}

std::optional<AmplitudeSpectrum::Peak> AmplitudeSpectrum::largestPeak(
    const std::function<bool(double)>& excluded) const {
  std::optional<std::size_t> best;
  for (std::size_t k = 1; k + 1 < amplitude_.size(); ++k) {
    const double a = amplitude_[k];
    if (!(a > 0.0) || a < amplitude_[k - 1] || a < amplitude_[k + 1]) continue;
    if (excluded(frequencyOfBin(k))) continue;
    if (!best || a > amplitude_[*best]) best = k;
  }
  if (!best) return std::nullopt;
  const std::size_t k = *best;
  double offset = 0.0;
  const double l = amplitude_[k - 1], c = amplitude_[k], r = amplitude_[k + 1];
  if (l > 0.0 && r > 0.0) {
    // Gaussian interpolation (parabola through the log-amplitudes), near-exact for a Hann main lobe.
    const double denominator = std::log(l) - 2.0 * std::log(c) + std::log(r);
    if (denominator < 0.0) offset = std::clamp(0.5 * (std::log(l) - std::log(r)) / denominator, -0.5, 0.5);
  }
  return Peak{(static_cast<double>(k) + offset) * bin_hz_, c};
}

}  // namespace mx
