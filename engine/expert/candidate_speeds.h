#pragma once
// The spindle speeds of the ranking grid of one tool: the regular grid from..to by step, plus the
// Pareto paper's Rule 7.2 initial candidates, the speeds whose tooth-passing frequency is a modal
// frequency or one of its sub-multiples, N = 60 f_n / (n_t k), k = 1, 2, ... (the lobe peaks, where
// the deepest stable cuts lie). SI: rev/s.
#include <vector>

#include "expert/expert_settings.h"
#include "model/milling_setup.h"

namespace mx {

// N = f_n / (n_t k) for every mode of both axes and every k >= 1 with N in [from, to], ascending. A tool
// without modes takes f_n from its measured FRFs instead: the line of largest |H| above 0 Hz per measured
// axis (an axis with neither contributes nothing).
std::vector<double> modalCandidateSpeeds(const MillingSetup& setup, double from_rev_per_s, double to_rev_per_s);

// The regular grid (as SpeedGrid::values) merged with modalCandidateSpeeds when grid.modal_candidate_speeds;
// ascending, duplicates (within 1e-9 relative) removed. Throws InvalidInput for a non-positive step
// or from > to, or more than 1e6 speeds.
std::vector<double> rankingSpeeds(const MillingSetup& setup, const ExpertGrid& grid);

}  // namespace mx
