#include "modal_fit/mode_selection.h"

#include <algorithm>
#include <cmath>

#include "modal_fit/lsfd.h"

namespace mx {
namespace {

struct Candidate {
  std::complex<double> pole;
  double amplitude;     // 1 / (2 zeta k) [m/N]
  double significance;  // amplitude / |H| measured nearest the mode's frequency
};

double measuredMagnitudeNear(const FrfBand& band, double frequency_hz) {
  const auto it = std::lower_bound(band.frequency_hz.begin(), band.frequency_hz.end(), frequency_hz);
  std::size_t i = static_cast<std::size_t>(it - band.frequency_hz.begin());
  if (i == band.size() || (i > 0 && frequency_hz - band.frequency_hz[i - 1] < band.frequency_hz[i] - frequency_hz)) --i;
  return std::abs(band.h_m_per_n[i]);
}

}  // namespace

std::vector<std::complex<double>> selectPoles(const FrfBand& band, const std::vector<std::complex<double>>& poles,
                                              std::optional<int> modes, int max_modes,
                                              const SelectionCriteria& criteria) {
  if (poles.empty()) return {};
  const FittedModel model = fittedModel(poles, fitResidues(band, poles));
  std::vector<Candidate> candidates;
  for (std::size_t r = 0; r < poles.size(); ++r) {
    const Mode& m = model.modes[r];
    if (!(m.stiffness_n_per_m > 0.0 && std::isfinite(m.stiffness_n_per_m))) continue;
    if (!(m.damping_ratio > 0.0 && m.damping_ratio < criteria.max_damping)) continue;
    const double amplitude = 1.0 / (2.0 * m.damping_ratio * m.stiffness_n_per_m);
    const double measured = measuredMagnitudeNear(band, m.natural_frequency_hz);
    candidates.push_back({poles[r], amplitude, measured > 0.0 ? amplitude / measured : 0.0});
  }
  if (!modes) std::erase_if(candidates, [&](const Candidate& c) { return c.significance < criteria.min_significance; });
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.amplitude > b.amplitude; });
  const auto keep = static_cast<std::size_t>(std::max(modes.value_or(max_modes), 0));
  if (candidates.size() > keep) candidates.resize(keep);
  std::vector<std::complex<double>> kept;
  for (const Candidate& c : candidates) kept.push_back(c.pole);
  return kept;
}

}  // namespace mx
