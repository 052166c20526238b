#pragma once
// The per-block feed-override table of an optimised part program, as CSV text (RFC 4180 quoting,
// '\n' line ends, C-locale numbers). Columns:
//   block,line,original_F_mm_min,new_F_mm_min,S_rpm,reason,predicted_force_N
// block is the 1-based block index (= line for files read by GcodeReader), feeds are in mm/min
// whatever the program units (inch programs are converted), empty cells for unknown values.
#include <limits>
#include <string>
#include <vector>

namespace mx {

struct FeedOverrideRow {
  std::size_t block = 0;                                                    // 1-based
  int line = 0;                                                             // 1-based
  double original_feed_m_per_s = std::numeric_limits<double>::quiet_NaN();  // NaN: no F in effect
  double new_feed_m_per_s = std::numeric_limits<double>::quiet_NaN();
  double speed_rev_per_s = std::numeric_limits<double>::quiet_NaN();
  double depth_m = 0.0;
  double predicted_force_N = std::numeric_limits<double>::quiet_NaN();
  bool feed_changed = false;
  bool speed_changed = false;
  std::string reason;  // empty when unchanged
};

class FeedOverrideTable {
 public:
  static std::string header();
  static std::string csv(const std::vector<FeedOverrideRow>& rows);
  static std::string quote(const std::string& field);
};

}  // namespace mx
