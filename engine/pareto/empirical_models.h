#pragma once
// Tool life (Pareto paper eq. 10, Taylor) and surface roughness (eq. 12) as power laws
//   y = K V^a b^c s_t^d,  V = pi D N [m/min], b [mm], s_t [mm/tooth].
// The exponents of Table 3 were assigned to the variables from Table 4's ratios
// (shared/notes/seed-reading.md): TOL = K1 V^-3.02 b^-1.14 s_t^-0.54, SURF = K2 V^0.4638 b^1.129
// s_t^0.4461. In these units the printed K1 = 1677110 and K2 = 6088 are off Table 4 by one factor
// each on all three rows (0.1096 and 6212); the calibrated K1 = 1.53e7 and K2 = 0.980 reproduce it
// (docs/fidelity.md). The constants come from the project (pareto.taylor, pareto.roughness).
#include <string>

namespace mx {

struct PowerLawModel {
  double k = 1.0;
  double speed_exponent = 0.0;  // on V [m/min]
  double depth_exponent = 0.0;  // on b [mm]
  double feed_exponent = 0.0;   // on s_t [mm/tooth]

  double evaluate(double cutting_speed_m_per_min, double depth_mm, double feed_mm_per_tooth) const;
  // Throws InvalidInput naming `name`.field, the value and the range: k > 0 finite, |exponent| <= 10.
  void validate(const std::string& name) const;
};

struct ParetoModels {
  PowerLawModel tool_life{1.53e7, -3.02, -1.14, -0.54};   // TOL [min]
  PowerLawModel roughness{0.980, 0.4638, 1.129, 0.4461};  // SURF [um]
};

// V = pi D N in m/min from the diameter [m] and the spindle speed [rev/s].
double cuttingSpeedMPerMin(double diameter_m, double speed_rev_per_s);

}  // namespace mx
