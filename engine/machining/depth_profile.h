#pragma once
// Workpiece depth of cut per block of a part program, from one of two sources:
//  - the Z levels of the program against a stock top: depth = stock_top - lowest Z of the move
//    (0 when the move stays above the stock top);
//  - a project profile: piecewise-constant depths along the feed path, as consecutive segments
//    (length, depth) measured along the cumulative length of the feed moves (G1/G2/G3); past the last
//    segment the depth is 0 (out of the part). A block spanning several segments gets the largest.
// Only feed moves cut: rapids, dwells and blocks without motion get depth 0.
#include <vector>

#include "gcode/gcode_interpreter.h"

namespace mx {

struct DepthSegment {
  double length_m = 0.0;  // > 0
  double depth_m = 0.0;   // >= 0
};

class DepthProfile {
 public:
  static DepthProfile fromStockTop(double stock_top_z_m);
  // Throws InvalidInput naming the segment for a non-positive length or a negative depth.
  static DepthProfile fromSegments(std::vector<DepthSegment> segments);

  // Depth [m] of a feed move starting at feed-path position path_start_m [m].
  double depthForMove(const GcodeMotion& move, double path_start_m) const;
  // Depth [m] of every block of a run (same order as run.motions).
  std::vector<double> blockDepths(const GcodeRun& run) const;

  bool fromZ() const { return from_z_; }
  double stockTop() const { return stock_top_m_; }

 private:
  bool from_z_ = true;
  double stock_top_m_ = 0.0;
  std::vector<DepthSegment> segments_;
  std::vector<double> ends_;  // cumulative segment ends
};

}  // namespace mx
