#pragma once
// Continuous force plant of the 2006 paper, eq. 21-23: feed drive 1/(tau_m s + 1) in cascade with the cutting
// process K_p/(tau_c s + 1), so G_c(s) = K_p / ((tau_m s + 1)(tau_c s + 1)), input the commanded feed velocity
// f_c (m/s), output the resultant cutting force F_p (N).
//
// K_p = K_c b a(phi_st, phi_ex, n_t) / (N n_t)  [N s/m], with N in rev/s, b in m, K_c in N/m^2.
// Immersion function (not defined by the paper; our definition): the revolution average of the summed
// chip-thickness factor sin(phi_j) of the engaged teeth, normalised by the feed per tooth,
//   a = n_t / (2 pi) * (cos phi_st - cos phi_ex),
// so that the mean force is K_c b s_t a with s_t = f / (N n_t). Full immersion (0..pi): a = n_t / pi.
#include "control/froh_discretization.h"

namespace mx {

struct CuttingProcess {
  double cutting_pressure_Pa = 1200e6;             // K_c (1200 N/mm^2, aluminium, 2006 example)
  double start_angle_rad = 0.0;                    // phi_st
  double exit_angle_rad = 3.14159265358979323846;  // phi_ex (full immersion)
  int teeth = 4;                                   // n_t
  double spindle_rev_s = 715.0 / 60.0;             // N
  double drive_time_constant_s = 1e-4;             // tau_m (0.1 ms, eq. 21)
  // tau_c; <= 0 selects defaultProcessTimeConstant (half a tooth period).
  double process_time_constant_s = 0.0;
};

// a(phi_st, phi_ex, n_t) as defined above; InvalidInput unless 0 <= phi_st < phi_ex <= pi and n_t >= 1.
double immersionFunction(double start_angle_rad, double exit_angle_rad, int teeth);
// tau_c = 1 / (2 n_t N): the first-order (Pade) approximation of averaging the chip load over one tooth period,
// (1 - e^{-s T_t}) / (s T_t) ~ 1 / (1 + s T_t / 2). Chosen on physical grounds, not from the -0.6 threshold.
double defaultProcessTimeConstant(int teeth, double spindle_rev_s);

struct ForcePlant {
  double gain_N_s_per_m = 0.0;  // K_p
  double tau_m_s = 0.0;
  double tau_c_s = 0.0;

  // x = (actual feed f_a [m/s], F / K_p [m/s]); y = K_p x2 = F [N].
  StateSpace2 stateSpace() const;
};

void validateCuttingProcess(const CuttingProcess& process);  // InvalidInput naming the field
double processTimeConstant(const CuttingProcess& process);   // tau_c actually used
double spindlePeriod(const CuttingProcess& process);         // T = 1 / N
ForcePlant makeForcePlant(const CuttingProcess& process, double depth_m);

}  // namespace mx
