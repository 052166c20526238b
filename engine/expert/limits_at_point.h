#pragma once
// What keeps a selected point of Q from cutting more: the constraint that one more grid step of
// depth, and one more of feed per tooth, would violate (AdmissibleGrid::violation; None when the next
// step is admissible too, i.e. the limit is not binding there). The operator reads it as "the depth is
// limited by the lobes, the feed by the feed drive".
#include "expert/admissible_grid.h"

namespace mx {

struct LimitsAtPoint {
  QConstraint depth = QConstraint::None;  // at b + depth step
  QConstraint feed = QConstraint::None;   // at s_t + feed step
  double next_depth_m = 0.0;
  double next_feed_per_tooth_m = 0.0;
};

LimitsAtPoint limitsAtPoint(const AdmissibleGrid& grid, double speed_rev_per_s, double depth_m,
                            double feed_per_tooth_m);

// Short machine-readable name: "stability", "spindle_power", "feed_drive", "feed_per_tooth",
// "spindle_speed", "speed_security", "grid", "none".
const char* constraintKey(QConstraint constraint);

}  // namespace mx
