#pragma once
// Time- and frequency-domain figures of one simulated cutting point for Rule 5 (eq. 18, 19) and
// Rule 6, read as in shared/notes/seed-reading.md:
//   t_s, M_p: from the per-tooth-period peaks of the resultant force from the first contact (t = 0):
//             final value = mean of the last revolution's peaks; M_p = max(0, max peak / final - 1);
//             t_s = end of the last tooth period whose peak lies outside +-5 % of the final value.
//   R12h = A(2 f_tp) / A(f_tp), R1ch = A_chatter / A(f_tp) from the resultant-force spectrum of the
//          evaluated window (A_chatter: the largest non-harmonic peak, ChatterIndicators::a_chatter).
//   Rule 6 compares A_chatter with the largest amplitude among f_tp and its harmonics.
#include "model/milling_setup.h"
#include "simulation/simulation_types.h"

namespace mx {

struct ResponseMetrics {
  double settling_time_s = 0.0;
  double overshoot = 0.0;  // fraction of the final value
  double r12h = 0.0;
  double r1ch = 0.0;
  double a_chatter = 0.0;
  double a_toothpass_max = 0.0;  // max over h f_tp, h = 1 .. below Nyquist (at most 50)
  bool chatter = false;          // the simulation's own verdict (eta / chip ratio), or diverged
  bool malfunction(double ratio = 1.0) const { return a_chatter > ratio * a_toothpass_max; }
};

// `result` must come from simulateMilling with record_every = 1 (every step in the trace).
ResponseMetrics responseMetrics(const MillingSetup& setup, const OperatingPoint& point, const SimulationResult& result,
                                int evaluated_revolutions);

}  // namespace mx
