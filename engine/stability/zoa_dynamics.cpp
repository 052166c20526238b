#include "stability/zoa_dynamics.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/invalid_input.h"

namespace mx {

namespace {

using cplx = std::complex<double>;
constexpr double kPi = std::numbers::pi;

ZoaAxisDynamics axisDynamics(const ModalAxis& modes, const std::optional<MeasuredAxis>& measured, DynamicsSource source,
                             std::string_view name) {
  if (source != DynamicsSource::Measured || !measured) return {&modes, nullptr};
  measured->validate(name);
  return {&modes, &*measured};
}

// Modal part of the chatter-frequency grid [rad/s]: uniform over [0.3 f_min, 3 f_max] plus a dense band
// of +-12 zeta around every mode, where the lobe minima lie.
void appendModalGrid(const std::vector<Mode>& modes, int samples, std::vector<double>& grid) {
  if (modes.empty()) return;
  double lo = modes.front().angularFrequency(), hi = lo;
  for (const Mode& m : modes) {
    lo = std::min(lo, m.angularFrequency());
    hi = std::max(hi, m.angularFrequency());
  }
  lo *= 0.3;
  hi *= 3.0;
  grid.reserve(grid.size() + static_cast<size_t>(samples) + modes.size() * 241);
  for (int i = 0; i < samples; ++i) grid.push_back(lo + (hi - lo) * i / (samples - 1));
  for (const Mode& m : modes) {
    const double band = 12.0 * std::max(m.damping_ratio, 1e-4) * m.angularFrequency();
    for (int i = -120; i <= 120; ++i) {
      const double w = m.angularFrequency() + band * i / 120.0;
      if (w > lo && w < hi) grid.push_back(w);
    }
  }
}

// Measured part [rad/s]: every line above 0 Hz, and where |H_{i+1} - H_i| > 1 % of max|H| (sharp peaks)
// n = min(subdivisions, ceil(|dH| / (1 % max|H|)) - 1) equally spaced frequencies inside the interval, so
// that the lobe curves through the interpolated FRF are resolved in speed.
void appendMeasuredGrid(const MeasuredAxis& axis, int subdivisions, std::vector<double>& grid) {
  const std::vector<double>& f = axis.frequency_hz;
  const std::vector<cplx>& h = axis.h_m_per_n;
  double h_max = 0.0;
  for (const cplx& v : h) h_max = std::max(h_max, std::abs(v));
  const double threshold = 0.01 * h_max;
  for (size_t i = 0; i < f.size(); ++i) {
    if (f[i] > 0.0) grid.push_back(2.0 * kPi * f[i]);
    if (i + 1 == f.size() || subdivisions <= 0 || !(threshold > 0.0)) continue;
    const double ratio = std::abs(h[i + 1] - h[i]) / threshold;
    if (!(ratio > 1.0)) continue;
    const int n = static_cast<int>(std::min<double>(subdivisions, std::ceil(ratio) - 1.0));
    for (int j = 1; j <= n; ++j) grid.push_back(2.0 * kPi * (f[i] + (f[i + 1] - f[i]) * j / (n + 1)));
  }
}

void validateMarginAndSpeeds(const ZoaDynamics& d, const std::vector<double>& speeds, double delta) {
  const double limit = smallestDecayRate(d.x.usedModes(), d.y.usedModes());
  if (!(delta >= 0.0) || delta >= limit) {
    std::ostringstream msg;
    msg << "delta = " << delta << " 1/s: must be in [0, " << limit
        << ") (below the smallest modal decay rate zeta*omega_n)";
    throw InvalidInput(msg.str());
  }
  for (double n : speeds)
    if (!(n > 0.0) || !std::isfinite(n)) throw InvalidInput("spindle speed must be > 0");
}

}  // namespace

const ModalAxis& ZoaAxisDynamics::usedModes() const {
  static const ModalAxis kNoModes;
  return measured != nullptr ? kNoModes : *modes;
}

ZoaDynamics zoaDynamics(const MillingSetup& setup, const std::vector<double>& speeds, const ZoaOptions& options) {
  if (options.dynamics == DynamicsSource::Measured && options.delta_per_s != 0.0) {
    std::ostringstream msg;
    msg << "delta = " << options.delta_per_s
        << " 1/s: a measured FRF gives G(i omega) only, not G(-delta + i omega), so delta must be 0 with "
           "measured dynamics (use fitted modes for a margin)";
    throw InvalidInput(msg.str());
  }
  const ZoaDynamics d{axisDynamics(setup.modes_x, setup.measured_x, options.dynamics, "measured_x"),
                      axisDynamics(setup.modes_y, setup.measured_y, options.dynamics, "measured_y")};
  if (!d.rigid()) validateMarginAndSpeeds(d, speeds, options.delta_per_s);
  return d;
}

std::vector<double> zoaChatterFrequencyGrid(const ZoaDynamics& d, const ZoaOptions& options) {
  std::vector<double> grid;
  std::vector<Mode> modes = d.x.usedModes();
  modes.insert(modes.end(), d.y.usedModes().begin(), d.y.usedModes().end());
  appendModalGrid(modes, std::max(options.frequency_samples, 16), grid);
  for (const ZoaAxisDynamics* axis : {&d.x, &d.y})
    if (axis->measured != nullptr) appendMeasuredGrid(*axis->measured, options.measured_subdivisions, grid);
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  return grid;
}

int zoaCharacteristicRoots(const DirectionalFactors& a, cplx gxx, cplx gyy, cplx roots[2]) {
  const cplx a0 = gxx * gyy * (a.xx * a.yy - a.xy * a.yx);
  const cplx a1 = a.xx * gxx + a.yy * gyy;
  if (std::abs(a0) < 1e-12 * std::norm(a1)) {
    if (std::abs(a1) == 0.0) return 0;
    roots[0] = -1.0 / a1;
    return 1;
  }
  const cplx disc = std::sqrt(a1 * a1 - 4.0 * a0);
  roots[0] = -(a1 + disc) / (2.0 * a0);
  roots[1] = -(a1 - disc) / (2.0 * a0);
  return 2;
}

LobeDiagram emptyZoaDiagram(const std::vector<double>& speeds, double delta_per_s) {
  LobeDiagram out;
  out.delta_per_s = delta_per_s;
  out.speed_rev_per_s = speeds;
  out.envelope_depth_m.assign(speeds.size(), LobeDiagram::kNone);
  out.envelope_chatter_hz.assign(speeds.size(), 0.0);
  return out;
}

}  // namespace mx
