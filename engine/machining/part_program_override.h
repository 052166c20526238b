#pragma once
// Part-program overrides: walks a G-code program block by block, takes each feed move's depth of cut
// (from the stock top and the program's Z levels, or from a project depth profile), asks a force
// controller for the feed of that block, and produces the edits for an optimised program (F per block,
// S where the expert system changed the speed, a comment with the reason on every changed block) and
// the per-block feed-override table.
// Modal F is respected: an F is written only where the feed the machine would use (given the edits
// above it) differs from the wanted one at the written resolution, so a changed block never leaks its
// feed into the following blocks. Air moves (depth 0) and plunges (pure -Z moves, which the lateral
// force model does not describe) keep the programmed feed unless told otherwise; a feed move without
// any F gets the controller's feed. Inch programs (G20) are converted both ways (in/min <-> m/s).
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "control/model_based_force_controller.h"
#include "gcode/gcode_interpreter.h"
#include "gcode/gcode_program.h"
#include "gcode/gcode_writer.h"
#include "machining/depth_profile.h"
#include "machining/feed_override_table.h"

namespace mx {

// What the controller is told about one feed move.
struct CutState {
  std::size_t block = 0;  // 0-based index
  int line = 0;
  double depth_m = 0.0;
  double speed_rev_per_s = 0.0;                                               // in effect (after S override)
  double programmed_feed_m_per_s = std::numeric_limits<double>::quiet_NaN();  // NaN when missing
  double path_position_m = 0.0;                                               // feed-path length before this block
  double length_m = 0.0;                                                      // this block's path length
};

struct FeedDecision {
  double feed_m_per_s = 0.0;
  double predicted_force_N = std::numeric_limits<double>::quiet_NaN();
  std::string reason;  // e.g. "force limit"
};

// The force controller seen by the overrider (the adaptive controller, or the model-based one).
using BlockFeedController = std::function<FeedDecision(const CutState&)>;

// Wraps a model-based controller (copied) as a BlockFeedController.
BlockFeedController modelBasedFeedController(const ModelBasedForceController& controller);

struct PartProgramOverrideSettings {
  double stock_top_z_m = 0.0;               // used when depth_profile is empty
  std::vector<DepthSegment> depth_profile;  // project profile along the feed path; empty: from Z
  double speed_rev_per_s = std::numeric_limits<double>::quiet_NaN();  // expert system's speed; NaN: keep S
  bool keep_plunge_feed = true;                                       // pure -Z feed moves keep the programmed feed
  int feed_decimals_mm = 1;                                           // F resolution written for G21 blocks (mm/min)
  int feed_decimals_inch = 2;                                         // for G20 blocks (in/min)
  GcodeInterpreterSettings interpreter;
};

struct PartProgramOverrideResult {
  GcodeProgram program;
  GcodeRun run;
  std::vector<double> depths_m;        // per block
  std::vector<GcodeBlockEdit> edits;   // per block
  std::vector<FeedOverrideRow> rows;   // one per feed move
  std::vector<GcodeWarning> warnings;  // reader, interpreter and overrider, by line
  std::size_t changed_blocks = 0;

  std::string writeProgram(const GcodeHeader& header) const { return GcodeWriter::write(program, edits, &header); }
  std::string csv() const { return FeedOverrideTable::csv(rows); }
};

class PartProgramOverrider {
 public:
  // Throws InvalidInput for an empty controller, a bad profile or a non-positive speed override.
  PartProgramOverrider(BlockFeedController controller, PartProgramOverrideSettings settings);

  // Throws InvalidInput when a feed move has no spindle speed (no S and no override) or the controller
  // returns a feed that is not > 0.
  PartProgramOverrideResult run(GcodeProgram program) const;
  PartProgramOverrideResult run(std::string_view text) const;

 private:
  BlockFeedController controller_;
  PartProgramOverrideSettings settings_;
  DepthProfile profile_;
};

}  // namespace mx
