#pragma once
// Time-domain model of the face-milling operation of Landers & Ulsoy (appendix, eq. A1-A12).
//   A1-A2  cutting and thrust pressures P_C = 0.29 f^-0.25 d^-0.13 (V/1000)^-0.72,
//          P_T = 0.16 f^-0.40 d^-0.41 (V/1000)^-0.58  [kN/mm^2, f and d in mm, V in m/min];
//   A3-A4  per-tooth forces on the tool, F_x = sum [-P_T f d cos(psi) cos(q) + P_C f d sin(q)] g(q),
//          F_y = sum [-P_T f d cos(psi) sin(q) - P_C f d cos(q)] g(q) (q from the feed direction +x);
//   A5     g(q): the tooth is in the cut. Here g comes from the part geometry: the tooth tip is over the
//          rectangular part and in the front half of the cutter (material not yet removed this pass);
//   A6-A9  separate tool and part structures, two uncoupled second-order modes each;
//   A10-A12 regenerative feed per tooth f_i = f_t cos(q) + dx cos(q) + dy sin(q) with the relative
//          displacement change over the regeneration delay (default: the tooth period, see docs).
// Integration: classical RK4 at a fixed step that divides the delay exactly, the delayed relative
// displacement read from a DelayHistory (grid samples and Hermite mid-points). Forces are on the tool;
// the part feels the reaction (docs/supervision-notes.md on the signs of A6-A9). SI in the API.
#include <array>
#include <cstdint>

#include "simulation/delay_history.h"

namespace mx {

struct StructuralMode {
  double natural_frequency_rad_s = 1000.0;
  double damping_ratio = 0.05;
  double stiffness_N_per_m = 1e7;
};

struct PressureLaw {  // P = c f^ef d^ed (V/1000)^ev, kN/mm^2 with f, d in mm and V in m/min
  double coefficient = 0.29;
  double feed_exponent = -0.25;
  double depth_exponent = -0.13;
  double speed_exponent = -0.72;
};

enum class RegenerationDelay { ToothPeriod, SpindleRevolution };

struct FaceMillingParameters {
  double tool_radius_m = 0.025;
  int teeth = 4;
  double spindle_speed_rpm = 1500.0;
  double lead_angle_rad = 0.2617993877991494;  // 15 deg (not given by the paper; docs)
  PressureLaw cutting{0.29, -0.25, -0.13, -0.72};
  PressureLaw thrust{0.16, -0.40, -0.41, -0.58};
  StructuralMode tool_x{4500.0, 0.07, 14e6};   // A6: 14 kN/mm
  StructuralMode tool_y{4100.0, 0.11, 14e6};   // A7
  StructuralMode part_x{2600.0, 0.09, 9.5e6};  // A8: 9.5 kN/mm
  StructuralMode part_y{2100.0, 0.22, 9.5e6};  // A9
  // Part: a rectangle [start, start + length] along the feed axis x, width across it centred at center_y.
  double part_start_x_m = 0.0;
  double part_length_m = 0.1;
  double part_width_m = 0.05;
  double part_center_y_m = 0.0;
  double step_s = 5e-5;  // requested RK4 step; rounded so that the delay is a whole number of steps
  RegenerationDelay delay = RegenerationDelay::ToothPeriod;
};

void validateFaceMillingParameters(const FaceMillingParameters& p);  // InvalidInput naming the field

struct FaceMillingOutput {
  double t_s = 0.0;
  double fx_N = 0.0, fy_N = 0.0;  // forces on the tool (A3-A4)
  double power_W = 0.0;           // V sum of tangential forces: instantaneous spindle cutting power
  double tool_x_m = 0.0;          // tool centre along the feed axis
  double regen_m = 0.0;           // |relative displacement change over the delay|
  int teeth_in_cut = 0;
};

struct RigidRevolution {  // static (rigid-structure) forces over one revolution in the full cut
  double fy_max_N = 0.0;  // F_Y = max |F_y|
  double power_mean_W = 0.0;
  double power_max_W = 0.0;
};

class FaceMillingProcess {
 public:
  explicit FaceMillingProcess(FaceMillingParameters parameters);  // throws InvalidInput

  void reset(double tool_x_m = 0.0);  // rest state, empty history, time 0, tool centre at tool_x_m
  void setFeedRate(double m_per_s);   // >= 0
  void setDepth(double m);            // >= 0
  void step();                        // one integration step
  void advance(double duration_s);    // whole steps covering duration_s (rounded to nearest)

  const FaceMillingOutput& output() const { return out_; }
  double time() const { return out_.t_s; }
  double stepSize() const { return dt_; }
  double delay() const { return delay_s_; }
  double cuttingSpeed() const { return v_cut_; }      // m/s
  double spindlePeriod() const { return period_s_; }  // s
  double feedRate() const { return feed_rate_; }
  double depth() const { return depth_; }
  const FaceMillingParameters& parameters() const { return p_; }
  std::int64_t steps() const { return steps_; }

  // Rigid forces at depth d and feed per tooth f in the full cut (no structure, no part edges).
  RigidRevolution rigidRevolution(double depth_m, double feed_per_tooth_m, int samples = 720) const;

 private:
  using State = std::array<double, 8>;  // tool x (q, v), tool y, part x, part y
  struct Forces {
    double fx = 0.0, fy = 0.0, power = 0.0;
    int in_cut = 0;
  };
  Forces forces(double t, double tool_x, double dx, double dy, bool rigid) const;
  State derivative(const State& s, double t, double tool_x, const AxisPosition& past, Forces* f) const;
  double pressureCoeff(const PressureLaw& law) const;  // c (V/1000)^ev d^ed, the h-free part

  FaceMillingParameters p_;
  double omega_ = 0.0, period_s_ = 0.0, v_cut_ = 0.0, delay_s_ = 0.0, dt_ = 0.0;
  std::int64_t delay_steps_ = 1;
  double feed_rate_ = 0.0, depth_ = 0.0;
  double kc_ = 0.0, kt_ = 0.0;  // pressure coefficients at the current depth (N per mm^(1+e) ...)
  State s_{};
  double tool_x_ = 0.0;
  std::int64_t steps_ = 0;
  DelayHistory history_;
  FaceMillingOutput out_;
};

}  // namespace mx
