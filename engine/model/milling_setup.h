#pragma once
// One tool in one cut: geometry, structural modes, cutting-force coefficients and immersion.
// Conventions (Rubio et al. 2006, eq. 4-7; Altintas 2000): feed along +x, the tooth angle phi is
// measured clockwise from +y, h_static = s_t sin(phi). SI units throughout.
#include <numbers>
#include <optional>
#include <string>
#include <vector>

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
  // Every model's cost grows with the teeth; no milling cutter has more.
  static constexpr int kMaxTeeth = 100;
  int teeth = 1;
  double diameter_m = 0.0;
  // Cutter geometry (docs/fidelity.md, "Real cutters"). Tooth j sits at toothAngleRad(j) from tooth 0 in
  // the direction of rotation; tooth j + 1 is pitchRad(j) ahead of tooth j, so tooth j cuts the surface
  // tooth j + 1 left pitchRad(j) / Omega earlier (its delay). At height z above the tool tip an edge lags
  // its tip by helixLagRad(z) = z tan(helix) / R. A runout offset moves one edge radially outwards.
  double helix_rad = 0.0;
  std::vector<double> pitch_rad;           // one per tooth, summing to 2 pi; empty: uniform 2 pi / teeth
  std::vector<double> runout_m;            // one per tooth; empty: none
  double tangential_coefficient_pa = 0.0;  // K_t [N/m^2] (eq. 2)
  double radial_ratio = 0.0;               // K_r = F_r / F_t (eq. 3)
  // Edge (ploughing) forces per unit b of an engaged edge, and the axial cutting and edge coefficients
  // (Altintas 2000, eq. 2.22: F_q = K_qc b h + K_qe b). They change the static forces, torque and power,
  // not the linear stability.
  double tangential_edge_n_per_m = 0.0;  // K_te
  double radial_edge_n_per_m = 0.0;      // K_re
  double axial_coefficient_pa = 0.0;     // K_ac
  double axial_edge_n_per_m = 0.0;       // K_ae
  // Process damping (the C_i / V model; docs/fidelity.md, "Process damping"): an engaged edge of
  // width b moving at v_n into the cut surface is pushed back by C_i b v_n / V, V = pi D N.
  double process_damping_n_per_m = 0.0;  // C_i
  ModalAxis modes_x;
  ModalAxis modes_y;
  // Measured receptance per axis; an axis may have a measured FRF, modes, both or neither (rigid).
  std::optional<MeasuredAxis> measured_x;
  std::optional<MeasuredAxis> measured_y;
  MillingDirection direction = MillingDirection::Up;
  double radial_depth_m = 0.0;
  Immersion immersion;  // derived from radial depth and diameter

  double toothPitchRad() const;           // the mean pitch, 2 pi / teeth
  double pitchRad(int tooth) const;       // pitch_rad[tooth], or the mean when uniform
  double toothAngleRad(int tooth) const;  // sum of pitchRad(k) for k < tooth
  double runoutM(int tooth) const;        // runout_m[tooth], or 0
  bool uniformPitch() const;              // no pitch list, or every pitch equal to the mean within 1e-9 rad
  bool hasRunout() const;                 // some runout offset differs from 0
  bool hasEdgeForces() const { return tangential_edge_n_per_m != 0.0 || radial_edge_n_per_m != 0.0; }
  double helixLagRad(double height_m) const;
  // The period after which the cut repeats: one tooth period when the pitch is uniform, else one revolution.
  int teethPerPrincipalPeriod() const { return uniformPitch() ? 1 : teeth; }
  // Throws InvalidInput naming the field, value and rule: 1 <= teeth <= kMaxTeeth, |helix| < 90 deg, pitch and runout
  // of length teeth, pitches > 0 summing to 360 deg within 1e-6 deg, runout finite and below D / 4.
  void validateGeometry() const;
  // Throws InvalidInput naming the field and value unless K_t, K_r and the edge, axial and process-damping
  // coefficients are finite and >= 0.
  void validateCoefficients() const;
  // The process damping per unit b [N s / m^2] at `spindle_rev_per_s`: C_i / V.
  double processDampingPerDepth(double spindle_rev_per_s) const;
};

// Tolerance on the sum of the pitch angles: the fixed interface's 1e-6 degree.
inline constexpr double kPitchSumToleranceRad = 1e-6 * std::numbers::pi / 180.0;

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
