#pragma once
// Chatter indicators from the evaluated window of a time-domain simulation:
//   eta = max|F_dyn| / max|F_static|            (2006, eq. 11; chatter when eta >= 1.3)
//   chip_ratio = max h_dyn / max h_static       (Pareto paper, Rule 15; chatter when >= 1.25)
// and spectra: the resultant force gives A_toothpass and A_chatter; the chatter frequency is the largest
// peak of the vibration spectrum sqrt(|X(f)|^2 + |Y(f)|^2) outside the bands of the forced harmonics
// (of the tooth-passing frequency, or of the spindle frequency for a cutter with unequal teeth).
// (With teeth leaving the cut, the largest non-harmonic peak of |F| can be an alias f_c +- k f_tp; the
// structure filters those out of the displacement, so the vibration spectrum picks the physical f_c.)
#include <vector>

#include "simulation/simulation_types.h"

namespace mx {

// Accumulated by the simulator over the evaluated window, at every integration step. The static
// (rigid-tool) values are evaluated at the same cutter angles as the dynamic ones.
struct WindowSignals {
  std::vector<double> force_n;   // resultant |F| at each step
  std::vector<double> x_m, y_m;  // tool displacement at each step
  double sample_rate_hz = 0.0;   // 1 / dt
  double max_force_n = 0.0;
  double max_static_force_n = 0.0;
  double max_chip_m = 0.0;
  double max_static_chip_m = 0.0;
  double peak_power_w = 0.0;
};

struct ChatterCriteria {
  double eta_threshold = 1.3;
  double chip_ratio_threshold = 1.25;
  int teeth = 1;
  double nominal_rev_per_s = 0.0;
  SpindleSpeedVariation ssv;  // widens the tooth-passing bands by the frequency modulation
  // Variable pitch or runout: the cut repeats only every revolution, so the forced response has every
  // spindle harmonic k N; those are forced, not chatter.
  bool forced_at_spindle_harmonics = false;
};

// Half-width of the band around the h-th harmonic of the forced fundamental f_0 (tooth-passing or
// spindle frequency) that is not counted as chatter: min(max(3 bins, 1 % of f_0), f_0 / 4), plus
// |a| h f_0 + 2 f_ss under SSV (the swing of a frequency-modulated harmonic).
double harmonicBandHz(int harmonic, double fundamental_hz, double bin_hz, const SpindleSpeedVariation& ssv);

ChatterIndicators detectChatter(const WindowSignals& window, const ChatterCriteria& criteria);

}  // namespace mx
