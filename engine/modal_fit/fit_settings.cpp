#include "modal_fit/fit_settings.h"

#include <cmath>
#include <sstream>
#include <string>

#include "core/invalid_input.h"
#include "modal_fit/frf_band.h"

namespace mx {
namespace {

void require(bool ok, const std::string& field, double value, const std::string& range) {
  if (ok) return;
  std::ostringstream message;
  message << "modal fit: " << field << " = " << value << ": must be " << range;
  throw InvalidInput(message.str());
}

std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string indexed(const char* name, std::size_t i) {
  std::ostringstream text;
  text << name << "[" << i << "]";
  return text.str();
}

std::string interval(double lo, double hi, const char* unit) {
  std::ostringstream text;
  text << "in [" << lo << ", " << hi << "]" << unit;
  return text.str();
}

void validateData(const std::vector<double>& f, const std::vector<std::complex<double>>& h) {
  require(h.size() == f.size(), "h_m_per_n size", static_cast<double>(h.size()),
          "the size of frequency_hz (" + std::to_string(f.size()) + ")");
  require(!f.empty(), "frequency_hz size", 0.0, "at least " + std::to_string(kMinBandPoints));
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!(std::isfinite(f[i]) && f[i] >= 0.0)) require(false, indexed("frequency_hz", i), f[i], "finite and >= 0 Hz");
    if (i > 0 && !(f[i] > f[i - 1])) require(false, indexed("frequency_hz", i), f[i], "> the previous frequency");
    if (!(std::isfinite(h[i].real()) && std::isfinite(h[i].imag())))
      require(false, indexed("h_m_per_n", i), std::abs(h[i]), "finite");
  }
}

}  // namespace

void validateFitInput(const std::vector<double>& frequency_hz, const std::vector<std::complex<double>>& h_m_per_n,
                      const ModalFitSettings& settings) {
  validateData(frequency_hz, h_m_per_n);
  const double lo = frequency_hz.front(), hi = frequency_hz.back();
  require(std::isfinite(settings.from_hz) && settings.from_hz >= lo && settings.from_hz < hi, "from_hz",
          settings.from_hz, interval(lo, hi, " Hz (the measured range, below to_hz)"));
  require(std::isfinite(settings.to_hz) && settings.to_hz <= hi, "to_hz", settings.to_hz,
          interval(lo, hi, " Hz (the measured range)"));
  require(settings.to_hz > settings.from_hz, "to_hz", settings.to_hz,
          "> from_hz = " + number(settings.from_hz) + " Hz");
  const auto points = selectBand(frequency_hz, h_m_per_n, settings.from_hz, settings.to_hz).size();
  require(points >= static_cast<std::size_t>(kMinBandPoints), "points in band", static_cast<double>(points),
          "at least " + std::to_string(kMinBandPoints) + " (widen [from_hz, to_hz])");
  require(settings.max_modes >= 1 && settings.max_modes <= kMaxModes, "max_modes", settings.max_modes,
          interval(1, kMaxModes, ""));
  if (settings.modes)
    require(*settings.modes >= 1 && *settings.modes <= settings.max_modes, "modes", *settings.modes,
            interval(1, settings.max_modes, " (max_modes)"));
}

}  // namespace mx
