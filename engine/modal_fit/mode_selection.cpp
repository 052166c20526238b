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

bool physical(const Mode& m, const SelectionCriteria& criteria) {
  return m.stiffness_n_per_m > 0.0 && std::isfinite(m.stiffness_n_per_m) && m.damping_ratio > 0.0 &&
         m.damping_ratio < criteria.max_damping;
}

}  // namespace

double resonanceAmplitude(const Mode& mode) {
  return 1.0 / (2.0 * mode.damping_ratio * mode.stiffness_n_per_m);
}

double significance(const FrfBand& band, const Mode& mode) {
  const double measured = measuredMagnitudeNear(band, mode.natural_frequency_hz);
  return measured > 0.0 ? resonanceAmplitude(mode) / measured : 0.0;
}

ModalAxis significantModes(const FrfBand& band, const ModalAxis& modes, const SelectionCriteria& criteria) {
  ModalAxis kept;
  for (const Mode& m : modes)
    if (physical(m, criteria) && significance(band, m) >= criteria.min_significance) kept.push_back(m);
  return kept;
}

ModalAxis distinctModes(const ModalAxis& modes) {
  ModalAxis sorted = modes;
  std::sort(sorted.begin(), sorted.end(),
            [](const Mode& a, const Mode& b) { return a.natural_frequency_hz < b.natural_frequency_hz; });
  ModalAxis kept;
  for (const Mode& m : sorted) {
    if (!kept.empty()) {
      Mode& last = kept.back();
      const double gap = 0.5 * std::min(last.damping_ratio, m.damping_ratio) * last.natural_frequency_hz;
      if (m.natural_frequency_hz - last.natural_frequency_hz <= gap) {
        if (resonanceAmplitude(m) > resonanceAmplitude(last)) last = m;
        continue;
      }
    }
    kept.push_back(m);
  }
  return kept;
}

std::vector<std::complex<double>> selectPoles(const FrfBand& band, const std::vector<std::complex<double>>& poles,
                                              std::optional<int> modes, int max_modes,
                                              const SelectionCriteria& criteria) {
  if (poles.empty()) return {};
  const FittedModel model = fittedModel(poles, fitResidues(band, poles));
  std::vector<Candidate> candidates;
  for (std::size_t r = 0; r < poles.size(); ++r) {
    const Mode& m = model.modes[r];
    if (physical(m, criteria)) candidates.push_back({poles[r], resonanceAmplitude(m), significance(band, m)});
  }
  if (!modes) std::erase_if(candidates, [&](const Candidate& c) { return c.significance < criteria.min_significance; });
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.amplitude > b.amplitude; });
  const auto keep = static_cast<std::size_t>(std::max(modes.value_or(max_modes), 0));
  if (candidates.size() > keep) candidates.resize(keep);
  std::vector<std::complex<double>> kept;
  kept.reserve(candidates.size());
  for (const Candidate& c : candidates) kept.push_back(c.pole);
  return kept;
}

}  // namespace mx
