#include "machining/afc_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "core/invalid_input.h"

namespace mx {
namespace {

constexpr double kMaxFmaxPercent = 999.0;  // the table's field holds three digits

std::string fixed(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

// Left-aligned in a column of `width` characters followed by a blank.
std::string cell(const std::string& text, std::size_t width) {
  std::string out = text;
  if (out.size() < width) out.append(width - out.size(), ' ');
  out += ' ';
  return out;
}

}  // namespace

AfcTeachIn afcFromPrediction(const AfcPrediction& p, const std::string& name, char ovld) {
  if (!(p.mean_power_W > 0.0) || !std::isfinite(p.mean_power_W))
    throw InvalidInput("AFC: predicted mean spindle power = " + fixed(p.mean_power_W, 1) +
                       " W: must be > 0 (a cut at the chosen point)");
  if (!(p.feed_per_tooth_m > 0.0) || !std::isfinite(p.feed_per_tooth_m))
    throw InvalidInput("AFC: feed per tooth = " + fixed(p.feed_per_tooth_m * 1e3, 4) + " mm: must be > 0");
  if (std::string_view("MSFEL-").find(ovld) == std::string_view::npos || ovld == '\0')
    throw InvalidInput(std::string("AFC: OVLD = '") + ovld + "': must be one of M, S, F, E, L, -");
  if (name.empty() || name.size() > kAfcNameLength)
    throw InvalidInput("AFC: name = '" + name + "': must have 1 to " + std::to_string(kAfcNameLength) + " characters");
  AfcTeachIn t;
  t.setting.name = name;
  t.setting.ovld = ovld;
  t.afc_load_W = p.mean_power_W;
  double ratio = std::numeric_limits<double>::infinity();
  t.fmax_limited_by = "none";
  if (p.max_feed_per_tooth_m > 0.0 && p.max_feed_per_tooth_m / p.feed_per_tooth_m < ratio)
    ratio = p.max_feed_per_tooth_m / p.feed_per_tooth_m, t.fmax_limited_by = "chip load";
  if (p.available_power_W > 0.0 && p.peak_power_W > 0.0 && p.available_power_W / p.peak_power_W < ratio)
    ratio = p.available_power_W / p.peak_power_W, t.fmax_limited_by = "spindle power";
  // Rounded down: the control may never pass the limit.
  t.setting.fmax_percent = std::isfinite(ratio) ? std::clamp(std::floor(100.0 * ratio), 100.0, kMaxFmaxPercent) : 100.0;
  if (t.setting.fmax_percent <= 100.0 && std::isfinite(ratio) && ratio < 1.0)
    t.fmax_limited_by += " (the point is already past it: AFC may not raise the feed)";
  return t;
}

std::string afcTableText(const AfcSetting& s) {
  std::string out = "BEGIN AFC .TAB MM\n";
  const char* columns[] = {"NR", "AFC", "FMIN", "FMAX", "FIDL", "FENT", "OVLD", "POUT", "SENS", "PLC"};
  const std::size_t widths[] = {4, kAfcNameLength, 5, 5, 5, 5, 4, 5, 5, 3};
  std::string header, row;
  const std::string values[] = {std::to_string(s.nr),     s.name,
                                fixed(s.fmin_percent, 0), fixed(s.fmax_percent, 0),
                                fixed(s.fidl_percent, 0), fixed(s.fent_percent, 0),
                                std::string(1, s.ovld),   fixed(s.pout_percent, 0),
                                fixed(s.sens_percent, 0), std::to_string(s.plc)};
  for (std::size_t i = 0; i < std::size(columns); ++i) {
    header += cell(columns[i], widths[i]);
    row += cell(values[i], widths[i]);
  }
  while (!header.empty() && header.back() == ' ') header.pop_back();
  while (!row.empty() && row.back() == ' ') row.pop_back();
  out += header + "\n" + row + "\n[END]\n";
  return out;
}

std::string afcToolTableText(int tool_number, const std::string& tool_name, const AfcTeachIn& t) {
  std::string out = "BEGIN TOOL .TAB MM\n";
  out += cell("T", 5) + cell("NAME", 16) + cell("AFC", kAfcNameLength) + "AFC-LOAD\n";
  out += cell(std::to_string(tool_number), 5) + cell(tool_name.substr(0, 16), 16) +
         cell(t.setting.name, kAfcNameLength) + fixed(t.afc_load_W * 1e-3, 3) + "\n";
  out += "[END]\n";
  return out;
}

}  // namespace mx
