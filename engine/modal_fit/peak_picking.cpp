#include "modal_fit/peak_picking.h"

#include <algorithm>
#include <optional>

namespace mx {
namespace {

struct Peak {
  double frequency_hz;
  double magnitude;
  double zeta;
};

std::vector<double> magnitudes(const FrfBand& band) {
  std::vector<double> m;
  m.reserve(band.size());
  for (const auto& h : band.h_m_per_n) m.push_back(std::abs(h));
  return m;
}

// Lowest |H| walking from p in direction step until a sample above |H|[p] or the end.
double valley(const std::vector<double>& m, std::size_t p, int step) {
  double lowest = m[p];
  for (auto i = static_cast<long>(p) + step; i >= 0 && i < static_cast<long>(m.size()); i += step) {
    if (m[i] > m[p]) break;
    lowest = std::min(lowest, m[i]);
  }
  return lowest;
}

// Vertex of the parabola through (x[i-1..i+1], y[i-1..i+1]) (Newton's divided differences).
std::pair<double, double> parabolaVertex(const std::vector<double>& x, const std::vector<double>& y, std::size_t i) {
  const double x0 = x[i - 1], x1 = x[i], x2 = x[i + 1];
  const double d01 = (y[i] - y[i - 1]) / (x1 - x0), d12 = (y[i + 1] - y[i]) / (x2 - x1);
  const double a = (d12 - d01) / (x2 - x0);
  if (a >= 0.0) return {x1, y[i]};
  const double b = d01 - a * (x0 + x1);
  const double xv = std::clamp(-b / (2.0 * a), x0, x2);
  return {xv, y[i - 1] + d01 * (xv - x0) + a * (xv - x0) * (xv - x1)};
}

// Frequency where |H| falls through `level` walking from p in direction step (linear interpolation).
std::optional<double> crossing(const std::vector<double>& f, const std::vector<double>& m, std::size_t p, int step,
                               double level) {
  for (auto i = static_cast<long>(p) + step; i >= 0 && i < static_cast<long>(m.size()); i += step) {
    if (m[i] >= level) continue;
    const long j = i - step;  // the last sample above the level
    return f[j] + (level - m[j]) / (m[i] - m[j]) * (f[i] - f[j]);
  }
  return std::nullopt;
}

std::optional<Peak> halfPowerPeak(const FrfBand& band, const std::vector<double>& m, std::size_t p) {
  const auto [fn, hmax] = parabolaVertex(band.frequency_hz, m, p);
  const double level = hmax / std::sqrt(2.0);
  const auto f1 = crossing(band.frequency_hz, m, p, -1, level);
  const auto f2 = crossing(band.frequency_hz, m, p, +1, level);
  if (!f1 || !f2 || *f2 <= *f1) return std::nullopt;
  return Peak{fn, hmax, (*f2 - *f1) / (2.0 * fn)};
}

}  // namespace

ModalAxis pickPeaks(const FrfBand& band, int max_peaks, double min_prominence) {
  const auto m = magnitudes(band);
  std::vector<Peak> peaks;
  for (std::size_t p = 1; p + 1 < m.size(); ++p) {
    if (!(m[p] > m[p - 1] && m[p] >= m[p + 1])) continue;
    const double reference = std::max(valley(m, p, -1), valley(m, p, +1));
    if (m[p] < min_prominence * reference) continue;
    if (const auto peak = halfPowerPeak(band, m, p)) peaks.push_back(*peak);
  }
  std::sort(peaks.begin(), peaks.end(), [](const Peak& a, const Peak& b) { return a.magnitude > b.magnitude; });
  if (peaks.size() > static_cast<std::size_t>(std::max(max_peaks, 0)))
    peaks.resize(static_cast<std::size_t>(max_peaks));
  ModalAxis modes;
  for (const Peak& p : peaks) modes.push_back({p.frequency_hz, p.zeta, 1.0 / (2.0 * p.zeta * p.magnitude)});
  std::sort(modes.begin(), modes.end(),
            [](const Mode& a, const Mode& b) { return a.natural_frequency_hz < b.natural_frequency_hz; });
  return modes;
}

}  // namespace mx
