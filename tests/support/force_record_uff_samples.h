#pragma once
// Test helpers for dynamometer records as universal files (cutting_data/force_record_uff.h): a record
// written as three datasets 58 of function type 1 in a chosen layout (ASCII or binary, single or double,
// even or uneven times, units, direction signs), and the record as that file holds it, in SI.
#include <array>
#include <cstdlib>
#include <string>
#include <vector>

#include "cutting_data/force_measurement_csv.h"
#include "support/frf_samples.h"

namespace mx::test {

struct ForceUffLayout {
  int ordinate_type = 4;  // 2 real single, 4 real double
  bool even = true;       // even: the times must be 0, dt, 2 dt, ...
  bool binary = false;
  std::string time_units = "s";
  double time_factor = 1.0;  // seconds per time unit
  std::string force_units = "N";
  double force_factor = 1.0;               // newtons per force unit
  std::array<int, 3> directions{1, 2, 3};  // record 6 response direction of Fx, Fy, Fz
  std::array<bool, 3> present{true, true, true};
};

// A value as the file stores it: E20.12 or E13.5 text, or a raw IEEE double or float.
inline double storedValue(double v, const ForceUffLayout& l) {
  const bool single = l.ordinate_type == 2;
  if (l.binary) return single ? static_cast<double>(static_cast<float>(v)) : v;
  return std::strtod(formatted(single ? "%13.5E" : "%20.12E", v).c_str(), nullptr);
}

// The record as the file of `layout` holds it, back in SI: what a reader must give.
inline ForceRecord storedRecord(const ForceRecord& r, const ForceUffLayout& l) {
  ForceRecord s;
  const double dt = r.t_s.size() > 1 ? r.t_s[1] - r.t_s[0] : 0.0;
  const double increment = std::strtod(formatted("%13.5E", dt / l.time_factor).c_str(), nullptr);
  for (std::size_t i = 0; i < r.t_s.size(); ++i)
    s.t_s.push_back(l.even ? static_cast<double>(i) * increment * l.time_factor
                           : storedValue(r.t_s[i] / l.time_factor, l) * l.time_factor);
  auto forces = [&](const std::vector<double>& f, std::vector<double>& out) {
    for (double v : f) out.push_back(storedValue(v / l.force_factor, l) * l.force_factor);
  };
  forces(r.fx_n, s.fx_n);
  forces(r.fy_n, s.fy_n);
  forces(r.fz_n, s.fz_n);
  return s;
}

// The dataset 58 of one force (axis 0 x, 1 y, 2 z); `block_bytes` < 0 declares the block's own size.
inline std::string forceDataset(const std::vector<double>& t_s, const std::vector<double>& f_n, int axis,
                                const ForceUffLayout& l, long block_bytes = -1) {
  Uff58Text u;
  u.name = std::string("cut F") + "xyz"[axis];
  u.function_type = 1;
  u.response_dir = l.directions[static_cast<std::size_t>(axis)];
  u.reference_node = 0;
  u.reference_dir = 0;
  u.ordinate_type = l.ordinate_type;
  u.points = static_cast<int>(t_s.size());
  u.spacing = l.even ? 1 : 0;
  u.x_min = 0.0;
  u.x_increment = t_s.size() > 1 ? (t_s[1] - t_s[0]) / l.time_factor : 1.0;
  u.abscissa_type = 17;
  u.abscissa_units = l.time_units;
  u.numerator_type = 13;
  u.numerator_units = l.force_units;
  u.denominator_type = 0;
  u.denominator_units = "NONE";
  const double sign = u.response_dir < 0 ? -1.0 : 1.0;
  std::vector<double> values;
  for (std::size_t i = 0; i < t_s.size(); ++i) {
    if (!l.even) values.push_back(t_s[i] / l.time_factor);
    values.push_back(sign * f_n[i] / l.force_factor);
  }
  if (l.binary) {
    const std::vector<float> single(values.begin(), values.end());
    const std::string block = l.ordinate_type == 2 ? rawBytes(single) : rawBytes(values);
    return u.binaryText(block, 1, block_bytes);
  }
  const char* format = l.ordinate_type == 2 ? "%13.5E" : "%20.12E";
  for (std::size_t i = 0; i < values.size(); i += 4) {
    std::string line;
    for (std::size_t k = i; k < std::min(i + 4, values.size()); ++k) line += formatted(format, values[k]);
    u.data.push_back(line);
  }
  return u.text();
}

// The record as a universal file: the present forces' datasets, x, y, z.
inline std::string forceRecordUff(const ForceRecord& r, const ForceUffLayout& l = {}) {
  const std::array<const std::vector<double>*, 3> forces{&r.fx_n, &r.fy_n, &r.fz_n};
  std::string text;
  for (int axis = 0; axis < 3; ++axis)
    if (l.present[static_cast<std::size_t>(axis)])
      text += forceDataset(r.t_s, *forces[static_cast<std::size_t>(axis)], axis, l);
  return text;
}

// The record as the CSV record reader takes it, every digit kept.
inline std::string forceRecordCsv(const ForceRecord& r) {
  std::string csv = "time_s,Fx_N,Fy_N,Fz_N\n";
  for (std::size_t i = 0; i < r.t_s.size(); ++i)
    csv += formatted("%.17g,%.17g,%.17g,%.17g\n", r.t_s[i], r.fx_n[i], r.fy_n[i], r.fz_n[i]);
  return csv;
}

}  // namespace mx::test
