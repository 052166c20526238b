#pragma once
// Settings of a modal fit and the checks of the fit's input.
#include <complex>
#include <optional>
#include <vector>

namespace mx {

struct ModalFitSettings {
  enum class Method { Lscf, Peak };

  double from_hz = 0.0;  // fitting band [from_hz, to_hz], inside the measured range
  double to_hz = 0.0;
  int max_modes = 10;        // LSCF model orders 2 .. 2 max_modes; most peaks picked
  std::optional<int> modes;  // modes to keep (the most significant); automatic when empty
  Method method = Method::Lscf;
  bool refine = true;  // nonlinear least-squares refinement after LSCF + LSFD
};

inline constexpr int kMinBandPoints = 8;
inline constexpr int kMaxModes = 50;

// Throws InvalidInput naming the field, its value and the allowed range: sizes differ, frequencies not
// finite and increasing, H not finite, from_hz >= to_hz, band outside the measured range, fewer than
// kMinBandPoints points in the band, max_modes outside [1, kMaxModes], modes outside [1, max_modes].
void validateFitInput(const std::vector<double>& frequency_hz, const std::vector<std::complex<double>>& h_m_per_n,
                      const ModalFitSettings& settings);

}  // namespace mx
