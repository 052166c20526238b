#pragma once
// One tool in one cut: geometry, structural modes, cutting-force coefficients and immersion.
// Conventions (Rubio et al. 2006, eq. 4-7; Altintas 2000): feed along +x, the tooth angle phi is
// measured clockwise from +y, h_static = s_t sin(phi). SI units throughout.
#include <optional>
#include <string>

#include "model/measured_receptance.h"
#include "model/modal_model.h"

namespace mx {

enum class MillingDirection { Up, Down };

// Where the ZOA takes the structural dynamics from: the modes, or each axis's measured FRF where it has
// one (docs/fidelity.md, "ZOA on a measured FRF").
enum class DynamicsSource { Modal, Measured };

struct Immersion {
  double entry_rad = 0.0;  // phi_st
  double exit_rad = 0.0;   // phi_ex

  // Up milling: phi_st = 0, phi_ex = acos(1 - 2a/D). Down milling: phi_st = acos(2a/D - 1), phi_ex = pi.
  static Immersion fromRadialDepth(double radial_depth_m, double diameter_m, MillingDirection direction);
  bool contains(double phi_rad) const;  // phi wrapped to [0, 2 pi)
};

struct MillingSetup {
  std::string tool_id;
  int teeth = 1;
  double diameter_m = 0.0;
  double helix_rad = 0.0;                  // carried, not modelled (straight-tooth model, docs/fidelity.md)
  double tangential_coefficient_pa = 0.0;  // K_t [N/m^2] (eq. 2)
  double radial_ratio = 0.0;               // K_r = F_r / F_t (eq. 3)
  ModalAxis modes_x;
  ModalAxis modes_y;
  // Measured receptance per axis; an axis may have a measured FRF, modes, both or neither (rigid).
  std::optional<MeasuredAxis> measured_x;
  std::optional<MeasuredAxis> measured_y;
  MillingDirection direction = MillingDirection::Up;
  double radial_depth_m = 0.0;
  Immersion immersion;  // derived from radial depth and diameter

  double toothPitchRad() const;
};

// A point in the cutting-parameter space Q = (N, b, s_t).
struct OperatingPoint {
  double spindle_rev_per_s = 0.0;  // N / 60
  double axial_depth_m = 0.0;      // b
  double feed_per_tooth_m = 0.0;   // s_t
  double toothPeriodS(int teeth) const { return 1.0 / (spindle_rev_per_s * teeth); }
};

inline constexpr double kRpmPerRevPerS = 60.0;
inline double rpmToRevPerS(double rpm) {
  return rpm / kRpmPerRevPerS;
}
inline double revPerSToRpm(double rev_per_s) {
  return rev_per_s * kRpmPerRevPerS;
}

}  // namespace mx
