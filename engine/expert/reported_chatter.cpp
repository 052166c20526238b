#include "expert/reported_chatter.h"

#include <cmath>
#include <sstream>

#include "core/invalid_input.h"

namespace mx {

namespace {

constexpr double kSlack = 1e-9;

void requirePositiveFinite(const std::string& name, const char* field, double value, const char* unit) {
  if (std::isfinite(value) && value > 0.0) return;
  std::ostringstream out;
  out << name << ": " << field << " = " << value << " " << unit << ": must be a finite number > 0";
  throw InvalidInput(out.str());
}

}  // namespace

bool ChatterRegion::contains(double speed_rev_per_s, double depth_m) const {
  return speed_rev_per_s >= speed_from_rev_per_s * (1.0 - kSlack) &&
         speed_rev_per_s <= speed_to_rev_per_s * (1.0 + kSlack) && depth_m >= depth_from_m * (1.0 - kSlack);
}

ChatterRegion chatterRegionOf(const ChatterReport& report) {
  ChatterRegion r;
  r.speed_from_rev_per_s = report.speed_rev_per_s * (1.0 - kReportedChatterSpeedBand);
  r.speed_to_rev_per_s = report.speed_rev_per_s * (1.0 + kReportedChatterSpeedBand);
  r.depth_from_m = report.depth_m;
  return r;
}

void validateChatterReport(const ChatterReport& report, std::size_t tool_count, const std::string& name) {
  if (report.tool >= tool_count) {
    std::ostringstream out;
    out << name << ": tool index " << report.tool << " is not one of the " << tool_count << " tools";
    throw InvalidInput(out.str());
  }
  requirePositiveFinite(name, "speed", report.speed_rev_per_s, "rev/s");
  requirePositiveFinite(name, "depth", report.depth_m, "m");
  if (report.frequency_hz) requirePositiveFinite(name, "frequency", *report.frequency_hz, "Hz");
}

bool reportHolds(const ChatterReport& report, std::size_t tool, const ExpertPoint& q) {
  return report.tool == tool && chatterRegionOf(report).contains(q.speed_rev_per_s, q.depth_m);
}

std::optional<std::size_t> reportHolding(const std::vector<ChatterReport>& reports, std::size_t tool,
                                         const ExpertPoint& q) {
  for (std::size_t i = 0; i < reports.size(); ++i)
    if (reportHolds(reports[i], tool, q)) return i;
  return std::nullopt;
}

}  // namespace mx
