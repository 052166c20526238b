// libFuzzer target for readUff: any bytes either throw FrfFileError or give FRFs that keep the reader's
// promises (as many values as frequencies, frequencies finite and strictly increasing, finite values)
// and that survive a 58b write and read bit for bit. Anything else aborts as a finding.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "frf/uff_reader.h"
#include "frf/uff_writer.h"

namespace {

bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void checkPromises(const mx::FrfDataset& d) {
  if (d.frequency_hz.size() != d.values.size() || d.values.empty()) std::abort();
  for (std::size_t i = 0; i < d.values.size(); ++i) {
    if (!std::isfinite(d.frequency_hz[i]) || !std::isfinite(d.values[i].real()) || !std::isfinite(d.values[i].imag()))
      std::abort();
    if (i > 0 && !(d.frequency_hz[i] > d.frequency_hz[i - 1])) std::abort();
  }
}

void checkBinaryRoundTrip(const mx::FrfFile& file) {
  const auto again = mx::readUff(mx::uff58bString(file.datasets), "round trip");
  if (again.datasets.size() != file.datasets.size()) std::abort();
  for (std::size_t k = 0; k < file.datasets.size(); ++k) {
    const auto& a = file.datasets[k];
    const auto& b = again.datasets[k];
    if (a.quantity != b.quantity || a.response_direction != b.response_direction ||
        a.reference_direction != b.reference_direction || a.values.size() != b.values.size())
      std::abort();
    for (std::size_t i = 0; i < a.values.size(); ++i)
      if (!sameBits(a.frequency_hz[i], b.frequency_hz[i]) || !sameBits(a.values[i].real(), b.values[i].real()) ||
          !sameBits(a.values[i].imag(), b.values[i].imag()))
        std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const auto file = mx::readUff(bytes, "fuzz.unv");
    for (const auto& d : file.datasets) checkPromises(d);
    checkBinaryRoundTrip(file);
  } catch (const mx::FrfFileError&) {
  }
  return 0;
}
