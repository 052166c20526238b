#include "expert/limits_at_point.h"

namespace mx {

LimitsAtPoint limitsAtPoint(const AdmissibleGrid& grid, double n, double b, double s) {
  LimitsAtPoint out;
  out.next_depth_m = b + grid.depthStep();
  out.next_feed_per_tooth_m = s + grid.feedStep();
  out.depth = grid.violation(n, out.next_depth_m, s);
  out.feed = grid.violation(n, b, out.next_feed_per_tooth_m);
  return out;
}

const char* constraintKey(QConstraint c) {
  switch (c) {
    case QConstraint::SpindleSpeed:
      return "spindle_speed";
    case QConstraint::Stability:
      return "stability";
    case QConstraint::FeedPerTooth:
      return "feed_per_tooth";
    case QConstraint::FeedDrive:
      return "feed_drive";
    case QConstraint::SpindlePower:
      return "spindle_power";
    case QConstraint::ToolForce:
      return "tool_force";
    case QConstraint::SpeedSecurity:
      return "speed_security";
    case QConstraint::OutsideGrid:
      return "grid";
    case QConstraint::None:
      break;
  }
  return "none";
}

}  // namespace mx
