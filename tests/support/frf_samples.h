#pragma once
// Test helpers for the FRF readers: FRFs synthesised from known modes, and universal-file dataset 58
// text built record by record (the UC-SDRL fixed formats) so that each test can change one field.
#include <algorithm>
#include <bit>
#include <complex>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "frf/frf_dataset.h"
#include "frf/modal_frf.h"
#include "model/modal_model.h"

namespace mx::test {

// The FRF of `axis` as `quantity` at the given frequencies (modal_frf.h).
inline FrfDataset modalFrf(const ModalAxis& axis, FrfQuantity quantity, const std::vector<double>& frequency_hz,
                           FrfDirection direction = FrfDirection::X) {
  return modalFrfDataset(axis, quantity, frequency_hz, direction, "modal " + std::string(frfQuantityName(quantity)));
}

// Writes `bytes` to `path` unchanged (binary), replacing the file.
inline void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

inline std::vector<double> evenFrequencies(double f0, double df, int n) {
  std::vector<double> f;
  f.reserve(static_cast<std::size_t>(std::max(n, 0)));
  for (int i = 0; i < n; ++i) f.push_back(f0 + i * df);
  return f;
}

inline const ModalAxis kTwoModes{{600.0, 0.03, 5e6}, {1500.0, 0.05, 2e7}};

template <typename... A>
std::string formatted(const char* fmt, A... args) {
  char buf[256];
  std::snprintf(buf, sizeof(buf), fmt, args...);
  return buf;
}

// One dataset 58 with its fields; text() gives "-1", "58", records 1-11, the data lines and "-1".
struct Uff58Text {
  std::string name = "tap x";
  int function_type = 4;
  int response_node = 1, response_dir = 1, reference_node = 1, reference_dir = 1;
  int ordinate_type = 6, points = 2, spacing = 1;
  double x_min = 0.0, x_increment = 1.0;
  int abscissa_type = 18;
  std::string abscissa_units = "Hz";
  int numerator_type = 8;
  std::string numerator_units = "m";
  int denominator_type = 13;
  std::string denominator_units = "N";
  std::vector<std::string> data;  // record 12 lines
  std::string eol = "\n";

  std::string records() const {
    std::string s = name + eol + "NONE" + eol + "NONE" + eol + "NONE" + eol + "NONE" + eol;
    s += formatted("%5d%10d%5d%10d %-10s%10d%4d %-10s%10d%4d", function_type, 1, 0, 0, "NONE", response_node,
                   response_dir, "NONE", reference_node, reference_dir) +
         eol;
    s += formatted("%10d%10d%10d%13.5E%13.5E%13.5E", ordinate_type, points, spacing, x_min, x_increment, 0.0) + eol;
    s += formatted("%10d%5d%5d%5d %-20s %-20s", abscissa_type, 0, 0, 0, "Frequency", abscissa_units.c_str()) + eol;
    s += formatted("%10d%5d%5d%5d %-20s %-20s", numerator_type, 1, 0, 0, "Response", numerator_units.c_str()) + eol;
    s += formatted("%10d%5d%5d%5d %-20s %-20s", denominator_type, 0, 1, 0, "Force", denominator_units.c_str()) + eol;
    s += formatted("%10d%5d%5d%5d %-20s %-20s", 0, 0, 0, 0, "NONE", "NONE") + eol;
    return s;
  }
  std::string text() const {
    std::string s = "    -1" + eol + "    58" + eol + records();
    for (const auto& l : data) s += l + eol;
    return s + "    -1" + eol;
  }
  // The 58b form with `block` as the binary data; declared_bytes < 0 declares block.size().
  std::string binaryText(const std::string& block, int byte_order = 1, long declared_bytes = -1) const {
    const long bytes = declared_bytes < 0 ? static_cast<long>(block.size()) : declared_bytes;
    return "    -1\n" + formatted("%6d%c%6d%6d%12d%12ld%6d%6d%12d%12d", 58, 'b', byte_order, 2, 11, bytes, 0, 0, 0, 0) +
           "\n" + records() + block + "    -1\n";
  }
};

// A minimal other dataset (e.g. 15 nodes, 151 header, 164 units) to be skipped.
inline std::string otherDataset(int number) {
  return "    -1\n" + formatted("%6d", number) + "\n         1         0         0         1 1.0E+00 2.0E+00\n    -1\n";
}

// Values as raw bytes in the given order.
template <typename T>
std::string rawBytes(const std::vector<T>& values, bool big_endian = false) {
  std::string out;
  for (T v : values) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (big_endian == (std::endian::native == std::endian::little))
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    out.append(b, sizeof(T));
  }
  return out;
}

}  // namespace mx::test
