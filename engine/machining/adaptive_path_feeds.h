#pragma once
// The adaptive beta-FROH force controller (2006 paper, section 4) run along a part program:
// the cutting feed moves (depth > 0), in program order, form the workpiece of one closed-loop
// simulation, as the controller meets them when the tool position is the integral of its own feed.
// Each cutting block then gets the mean feed with which the simulated tool crossed its stretch of
// the path (length / time spent, so the block lasts as long as in the simulation) and the largest
// continuous force there. Air moves and plunges are left to the overrider (programmed feed).
#include <cstddef>
#include <map>
#include <optional>
#include <vector>

#include "control/closed_loop.h"
#include "machining/part_program_override.h"

namespace mx {

struct CutBlock {
  std::size_t block = 0;  // index in the program
  double length_m = 0.0;  // > 0
  double depth_m = 0.0;   // > 0
};

class AdaptivePathFeeds {
 public:
  // Throws InvalidInput when there is no cutting block, and whatever the closed loop throws.
  AdaptivePathFeeds(const AdaptiveControlSettings& base, const std::vector<CutBlock>& cuts, const JobControl& job = {});

  // The controller's decision for a cutting block; nullopt for a block that is not in `cuts`.
  std::optional<FeedDecision> decisionFor(std::size_t block) const;
  const ClosedLoopResult& run() const { return run_; }

 private:
  double timeAtPosition(double position_m) const;  // first time the tool reaches the position
  ClosedLoopResult run_;
  std::map<std::size_t, FeedDecision> decisions_;
};

// The cutting blocks of an override run: feed moves with depth > 0 and length > 0, except pure +Z
// retracts and (when exclude_plunges, i.e. keep_plunge_feed) pure -Z plunges.
std::vector<CutBlock> cuttingBlocks(const GcodeRun& run, const std::vector<double>& depths_m, bool exclude_plunges);

// A BlockFeedController answering from `feeds` (which must outlive it); blocks it does not know get
// the programmed feed.
BlockFeedController adaptiveFeedController(const AdaptivePathFeeds& feeds);

}  // namespace mx
