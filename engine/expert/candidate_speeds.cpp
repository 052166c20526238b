#include "expert/candidate_speeds.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/invalid_input.h"
#include "stability/lobe_diagram.h"

namespace mx {

namespace {

// Frequency [Hz] of the largest |H| among the lines above 0 Hz; 0 when there is none.
double peakFrequencyHz(const MeasuredAxis& axis) {
  double peak_hz = 0.0, peak = 0.0;
  const std::size_t lines = std::min(axis.frequency_hz.size(), axis.h_m_per_n.size());
  for (std::size_t i = 0; i < lines; ++i) {
    const double f = axis.frequency_hz[i], magnitude = std::abs(axis.h_m_per_n[i]);
    if (f > 0.0 && std::isfinite(f) && std::isfinite(magnitude) && magnitude > peak) peak_hz = f, peak = magnitude;
  }
  return peak_hz;
}

// The modal frequencies of both axes; for a tool without modes, the |H| peak of each measured FRF.
std::vector<double> candidateFrequenciesHz(const MillingSetup& setup) {
  std::vector<double> out;
  for (const ModalAxis* axis : {&setup.modes_x, &setup.modes_y})
    for (const Mode& mode : *axis) out.push_back(mode.natural_frequency_hz);
  if (!out.empty()) return out;
  for (const std::optional<MeasuredAxis>* axis : {&setup.measured_x, &setup.measured_y}) {
    const double f = *axis ? peakFrequencyHz(**axis) : 0.0;
    if (f > 0.0) out.push_back(f);
  }
  return out;
}

}  // namespace

std::vector<double> modalCandidateSpeeds(const MillingSetup& setup, double from, double to) {
  std::vector<double> out;
  for (const double f_hz : candidateFrequenciesHz(setup)) {
    for (int k = 1;; ++k) {
      const double n = f_hz / (setup.teeth * static_cast<double>(k));
      if (n < from || k > 100000) break;
      if (n <= to) out.push_back(n);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<double> rankingSpeeds(const MillingSetup& setup, const ExpertGrid& grid) {
  const double from = grid.speed_from_rev_per_s, to = grid.speed_to_rev_per_s, step = grid.speed_step_rev_per_s;
  if (!(from > 0.0 && to >= from && step > 0.0) || (to - from) / step > 1e6) {
    std::ostringstream msg;
    msg << "expert speed grid " << from * 60.0 << " .. " << to * 60.0 << " rpm by " << step * 60.0
        << " rpm: needs 0 < from <= to, step > 0 and at most 1e6 speeds";
    throw InvalidInput(msg.str());
  }
  std::vector<double> speeds = SpeedGrid{from, to, step}.values();
  if (grid.modal_candidate_speeds) {
    const std::vector<double> modal = modalCandidateSpeeds(setup, from, to);
    speeds.insert(speeds.end(), modal.begin(), modal.end());
    std::sort(speeds.begin(), speeds.end());
  }
  std::vector<double> unique;
  for (double n : speeds)
    if (unique.empty() || std::abs(n - unique.back()) > 1e-9 * n) unique.push_back(n);
  return unique;
}

}  // namespace mx
