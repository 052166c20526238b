// Fuzz target of readUff (universal file datasets 58 and 58b): any bytes either throw FrfFileError or
// give FRFs that keep the reader's promises (as many values as frequencies, frequencies finite and
// strictly increasing, finite values) and that survive a 58b write and read bit for bit.
#include <bit>
#include <cstdint>

#include "frf/uff_reader.h"
#include "frf/uff_writer.h"
#include "fuzz_check.h"

namespace {

using mx::fuzz::require;

bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void checkPromises(const mx::FrfDataset& d) {
  require(d.frequency_hz.size() == d.values.size() && !d.values.empty(), "one value per frequency, at least one");
  for (std::size_t i = 0; i < d.values.size(); ++i) {
    require(std::isfinite(d.frequency_hz[i]) && std::isfinite(d.values[i].real()) && std::isfinite(d.values[i].imag()),
            "finite frequencies and values");
    require(i == 0 || d.frequency_hz[i] > d.frequency_hz[i - 1], "strictly increasing frequencies");
  }
}

void checkBinaryRoundTrip(const mx::FrfFile& file) {
  const auto again = mx::readUff(mx::uff58bString(file.datasets), "round trip");
  require(again.datasets.size() == file.datasets.size(), "58b round trip keeps every dataset");
  for (std::size_t k = 0; k < file.datasets.size(); ++k) {
    const auto& a = file.datasets[k];
    const auto& b = again.datasets[k];
    require(a.quantity == b.quantity && a.response_direction == b.response_direction &&
                a.reference_direction == b.reference_direction && a.values.size() == b.values.size(),
            "58b round trip keeps quantity, directions and length");
    for (std::size_t i = 0; i < a.values.size(); ++i)
      require(sameBits(a.frequency_hz[i], b.frequency_hz[i]) && sameBits(a.values[i].real(), b.values[i].real()) &&
                  sameBits(a.values[i].imag(), b.values[i].imag()),
              "58b round trip is bit for bit");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto file = mx::readUff(mx::fuzz::bytesOf(data, size), "fuzz.unv");
    for (const auto& d : file.datasets) checkPromises(d);
    checkBinaryRoundTrip(file);
  } catch (const mx::FrfFileError&) {
  }
  return 0;
}
