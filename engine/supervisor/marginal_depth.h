#pragma once
// The appendix's search for the marginal depth of cut (Landers & Ulsoy): simulate A1-A12 at a fixed
// depth in the full cut, judge stability from the simulated signals, and bisect on the depth until the
// stable and unstable depths are within a tolerance.
// Chatter indicator: the RMS of the regenerative displacement |delta(t) - delta(t - T)| (A11-A12) over the
// last revolutions, divided by the nominal feed per tooth. The forced, tooth-periodic response makes it
// vanish in a stable cut; chatter makes it grow until teeth leave the cut (a fraction of the feed).
#include <vector>

#include "core/cancellation.h"
#include "core/invalid_input.h"
#include "supervisor/face_milling_process.h"

namespace mx {

struct MarginalDepthSettings {
  double depth_low_m = 0.25e-3;      // bracket: expected stable ...
  double depth_high_m = 4e-3;        // ... and expected unstable
  double tolerance_m = 0.02e-3;      // stop when high - low < tolerance
  double feed_per_tooth_m = 0.1e-3;  // 10 mm/s at 1500 rpm with 4 teeth
  int revolutions = 40;              // simulated revolutions per trial
  int tail_revolutions = 10;         // indicator window at the end
  double threshold = 0.02;           // indicator above this: chatter
};

void validateMarginalDepthSettings(const MarginalDepthSettings& s);  // InvalidInput naming the field

struct DepthTrial {
  double depth_m = 0.0;
  double indicator = 0.0;
  bool chatter = false;
};

struct MarginalDepthResult {
  double marginal_depth_m = 0.0;  // mid-point of the final bracket
  double stable_depth_m = 0.0;    // largest depth found stable
  double unstable_depth_m = 0.0;  // smallest depth found unstable
  bool bracketed = false;         // false: the bracket ends did not straddle the boundary
  std::vector<DepthTrial> trials;
};

class MarginalDepthSearch {
 public:
  // `process` supplies the tool, cutting and structural parameters; the part is replaced by a long one.
  MarginalDepthSearch(const FaceMillingParameters& process, MarginalDepthSettings settings);  // throws InvalidInput

  DepthTrial trial(double depth_m) const;                        // one simulation and its verdict
  MarginalDepthResult search(const JobControl& job = {}) const;  // bisection; throws Cancelled

  const MarginalDepthSettings& settings() const { return s_; }

 private:
  FaceMillingParameters p_;
  MarginalDepthSettings s_;
};

}  // namespace mx
