#pragma once
// Chatter observed at the machine (heard, or seen on a spectrum) as evidence for Rule 6 of the 2006
// expert system: "while A_chatter > A_toothpass" is then decided by the shop, not by our linear
// simulation. A report at (N_r, b_r) marks a region of the (N, b) plane of that tool as chattering:
// speeds within +-2 % of N_r (spindle speed wanders by about that much under load, and a lobe is
// wider than that) at the reported depth and deeper (at a fixed speed the lobes give one stability
// threshold in depth, so a deeper cut chatters too). SI units.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "expert/admissible_grid.h"

namespace mx {

inline constexpr double kReportedChatterSpeedBand = 0.02;  // +-2 % of the reported speed

struct ChatterReport {
  std::size_t tool = 0;  // index into the session's tools
  double speed_rev_per_s = 0.0;
  double depth_m = 0.0;
  std::optional<double> frequency_hz;  // the chatter frequency, when known (reported back, not used)
};

struct ChatterRegion {
  double speed_from_rev_per_s = 0.0;
  double speed_to_rev_per_s = 0.0;
  double depth_from_m = 0.0;
  // Inclusive, with a relative slack of 1e-9 so that a report typed from a printed grid point holds it.
  bool contains(double speed_rev_per_s, double depth_m) const;
};

ChatterRegion chatterRegionOf(const ChatterReport& report);

// Throws InvalidInput naming `name` (e.g. "reported chatter #2") and the bad value: tool index out of
// range, a non-finite or non-positive speed, depth or frequency.
void validateChatterReport(const ChatterReport& report, std::size_t tool_count, const std::string& name);

// True when q, a point of `tool`, lies in the region of a report of that tool.
bool reportHolds(const ChatterReport& report, std::size_t tool, const ExpertPoint& q);

// The first report of `tool` whose region holds q; nullopt when q is clear of every report.
std::optional<std::size_t> reportHolding(const std::vector<ChatterReport>& reports, std::size_t tool,
                                         const ExpertPoint& q);

}  // namespace mx
