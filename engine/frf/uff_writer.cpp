#include "frf/uff_writer.h"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <sstream>

#include "core/invalid_input.h"

namespace mx {
namespace {

constexpr int kComplexDouble = 6;

std::string format(const char* fmt, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof(buf), fmt, args...);
  return buf;
}

void check(const FrfDataset& d) {
  if (d.frequency_hz.size() != d.values.size())
    throw InvalidInput("FRF values = " + std::to_string(d.values.size()) + " for " +
                       std::to_string(d.frequency_hz.size()) + " frequencies (must be as many)");
}

struct NumeratorRecord {
  int type;
  const char* label;
  const char* units;
};

NumeratorRecord numerator(FrfQuantity q) {
  switch (q) {
    case FrfQuantity::Receptance:
      return {8, "Displacement", "m"};
    case FrfQuantity::Mobility:
      return {11, "Velocity", "m/s"};
    case FrfQuantity::Accelerance:
      return {12, "Acceleration", "m/s^2"};
  }
  return {8, "Displacement", "m"};
}

int direction(FrfDirection d) {
  return static_cast<int>(d) + 1;
}

// Records 1-11 (the UC-SDRL formats: 80A1; 2(I5,I10),2(1X,10A1,I10,I4); 3I10,3E13.5; I10,3I5,2(1X,20A1)).
void writeHeader(std::ostream& out, const FrfDataset& d) {
  std::string name = d.name.substr(0, 80);
  for (char& c : name)
    if (c == '\n' || c == '\r') c = ' ';
  out << name << "\nNONE\nNONE\nNONE\nNONE\n";
  out << format("%5d%10d%5d%10d %-10s%10d%4d %-10s%10d%4d\n", 4, d.index, 0, 0, "NONE", d.response_node,
                direction(d.response_direction), "NONE", d.reference_node, direction(d.reference_direction));
  const double f0 = d.frequency_hz.empty() ? 0.0 : d.frequency_hz.front();
  out << format("%10d%10zu%10d%13.5E%13.5E%13.5E\n", kComplexDouble, d.frequency_hz.size(), 0, f0, 0.0, 0.0);
  const auto n = numerator(d.quantity);
  out << format("%10d%5d%5d%5d %-20s %-20s\n", 18, 0, 0, 0, "Frequency", "Hz");
  out << format("%10d%5d%5d%5d %-20s %-20s\n", n.type, 1, 0, 0, n.label, n.units);
  out << format("%10d%5d%5d%5d %-20s %-20s\n", 13, 0, 1, 0, "Force", "N");
  out << format("%10d%5d%5d%5d %-20s %-20s\n", 0, 0, 0, 0, "NONE", "NONE");
}

void appendLittleEndian(std::string& out, double v) {
  const auto u = std::bit_cast<std::uint64_t>(v);
  for (int i = 0; i < 8; ++i) out += static_cast<char>((u >> (8 * i)) & 0xffu);
}

}  // namespace

void writeUff58(std::ostream& out, const std::vector<FrfDataset>& datasets) {
  for (const auto& d : datasets) {
    check(d);
    out << "    -1\n    58\n";
    writeHeader(out, d);
    for (std::size_t i = 0; i < d.values.size(); ++i)
      out << format("%20.12E%20.12E%20.12E\n", d.frequency_hz[i], d.values[i].real(), d.values[i].imag());
    out << "    -1\n";
  }
}

void writeUff58b(std::ostream& out, const std::vector<FrfDataset>& datasets) {
  for (const auto& d : datasets) {
    check(d);
    std::string block;
    block.reserve(d.values.size() * 24);
    for (std::size_t i = 0; i < d.values.size(); ++i) {
      appendLittleEndian(block, d.frequency_hz[i]);
      appendLittleEndian(block, d.values[i].real());
      appendLittleEndian(block, d.values[i].imag());
    }
    out << "    -1\n";
    out << format("%6d%c%6d%6d%12d%12zu%6d%6d%12d%12d\n", 58, 'b', 1, 2, 11, block.size(), 0, 0, 0, 0);
    writeHeader(out, d);
    out.write(block.data(), static_cast<std::streamsize>(block.size()));
    out << "    -1\n";
  }
}

std::string uff58String(const std::vector<FrfDataset>& datasets) {
  std::ostringstream out;
  writeUff58(out, datasets);
  return out.str();
}

std::string uff58bString(const std::vector<FrfDataset>& datasets) {
  std::ostringstream out;
  writeUff58b(out, datasets);
  return out.str();
}

}  // namespace mx
