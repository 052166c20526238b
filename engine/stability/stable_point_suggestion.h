#pragma once
// A chatter-free operating point near a chattering one, checked on the lobes before it is offered
// (Pareto paper, Rule 16, with the stability boundary as the judge):
//   1. the Smith-Tlusty speed N_k = f_c / (n_t k) nearest the current speed that is stable at this depth;
//   2. else the stable speed nearest the current one at this depth: the peak of alpha b_lim over the
//      nearest stretch of speeds where the depth is stable;
//   3. else, when no speed of the range is stable at this depth, the deepest stable depth at the nearest
//      pocket: the nearest local maximum of alpha b_lim, at kPocketDepthShare of it.
// Speeds within kSameSpeed of the current one are not offered (the lobes and a simulation disagree there).
#include <optional>

#include "stability/stability_boundary.h"

namespace mx {

struct StablePointSuggestion {
  enum class Kind { SmithTlusty, NearestStableSpeed, ShallowerDepth };
  Kind kind = Kind::SmithTlusty;
  double speed_rev_per_s = 0.0;
  double depth_m = 0.0;  // the current depth, except for ShallowerDepth
  int k = 0;             // Smith-Tlusty k (SmithTlusty only)
};

inline constexpr double kPocketDepthShare = 0.99;
inline constexpr double kSameSpeed = 0.01;  // relative

// chatter_hz: the chatter frequency, when known (Smith-Tlusty candidates); [min, max]: the machine's
// speeds (intersected with the boundary's). nullopt when the range holds no computed speed.
std::optional<StablePointSuggestion> suggestStablePoint(const StabilityBoundary& boundary, double speed_rev_per_s,
                                                        double depth_m, std::optional<double> chatter_hz, int teeth,
                                                        double min_rev_per_s, double max_rev_per_s);

}  // namespace mx
