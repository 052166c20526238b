#include "machining/feed_override_table.h"

#include <cmath>

#include "gcode/gcode_writer.h"

namespace mx {

std::string FeedOverrideTable::header() {
  return "block,line,original_F_mm_min,new_F_mm_min,S_rpm,reason,predicted_force_N\n";
}

std::string FeedOverrideTable::quote(const std::string& f) {
  if (f.find_first_of(",\"\r\n") == std::string::npos) return f;
  std::string s = "\"";
  for (char c : f) {
    if (c == '"') s += '"';
    s += c;
  }
  s += '"';
  return s;
}

std::string FeedOverrideTable::csv(const std::vector<FeedOverrideRow>& rows) {
  auto num = [](double v, int decimals) {
    return std::isfinite(v) ? GcodeWriter::formatNumber(v, decimals) : std::string();
  };
  std::string out = header();
  out.reserve(out.size() + rows.size() * 48);
  for (const auto& r : rows) {
    out += std::to_string(r.block);
    out += ',';
    out += std::to_string(r.line);
    out += ',';
    out += num(r.original_feed_m_per_s * 60e3, 3);
    out += ',';
    out += num(r.new_feed_m_per_s * 60e3, 3);
    out += ',';
    out += num(r.speed_rev_per_s * 60.0, 1);
    out += ',';
    out += quote(r.reason);
    out += ',';
    out += num(r.predicted_force_N, 2);
    out += '\n';
  }
  return out;
}

}  // namespace mx
