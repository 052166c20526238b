#pragma once
// What both zeroth-order paths (uniform and variable pitch) share: the structure seen on each axis, the
// chatter-frequency grid they scan, the eigenvalues of the oriented transfer function and the checks.
#include <complex>
#include <optional>
#include <string_view>
#include <vector>

#include "model/cutting_force.h"
#include "model/milling_setup.h"
#include "stability/zero_order_lobes.h"

namespace mx {

// The dynamics the ZOA sees on one axis: the measured FRF (DynamicsSource::Measured and one present),
// else the modes (none: rigid).
struct ZoaAxisDynamics {
  const ModalAxis* modes = nullptr;
  const MeasuredAxis* measured = nullptr;

  bool rigid() const { return measured == nullptr && modes->empty(); }
  // A measured FRF is known on the imaginary axis only (delta = 0 is enforced with it).
  std::complex<double> at(std::complex<double> s) const {
    return measured != nullptr ? measured->at(s.imag()) : receptance(*modes, s);
  }
  const ModalAxis& usedModes() const;
};

struct ZoaDynamics {
  ZoaAxisDynamics x;
  ZoaAxisDynamics y;
  bool rigid() const { return x.rigid() && y.rigid(); }
};

// Picks each axis's dynamics and checks the inputs: delta != 0 with measured dynamics and an invalid
// measured FRF always; delta outside [0, smallest decay rate) and speeds <= 0 only for a tool that is not
// rigid (a rigid tool has no lobes). Throws InvalidInput.
ZoaDynamics zoaDynamics(const MillingSetup& setup, const std::vector<double>& speeds_rev_per_s,
                        const ZoaOptions& options);

// Chatter frequencies to scan [rad/s], ascending: uniform over [0.3 f_min, 3 f_max] plus a dense band of
// +-12 zeta around every mode, and the measured lines (refined where the FRF changes fast).
std::vector<double> zoaChatterFrequencyGrid(const ZoaDynamics& dynamics, const ZoaOptions& options);

// Eigenvalues Lambda of det(I + Lambda [alpha][G]) = 0 (Budak & Altintas 1998):
// a0 Lambda^2 + a1 Lambda + 1 = 0, a0 = Gxx Gyy (axx ayy - axy ayx), a1 = axx Gxx + ayy Gyy.
// Returns how many there are (0-2; 1 when a0 vanishes, e.g. one axis rigid).
int zoaCharacteristicRoots(const DirectionalFactors& a, std::complex<double> gxx, std::complex<double> gyy,
                           std::complex<double> roots[2]);

// The diagram with the requested speeds, no lobes and the envelope at kNone everywhere.
LobeDiagram emptyZoaDiagram(const std::vector<double>& speeds_rev_per_s, double delta_per_s);

}  // namespace mx
