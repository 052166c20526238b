// Fuzz target of readFrfCsv: any bytes either throw FrfFileError or give an FRF with as many values
// as frequencies, strictly increasing frequencies, and a CSV write that reads back bit for bit.
#include <cstdint>

#include "frf/frf_csv.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using mx::fuzz::require;
  try {
    const auto d = mx::readFrfCsv(mx::fuzz::bytesOf(data, size), "fuzz.csv", mx::FrfQuantity::Receptance);
    require(d.frequency_hz.size() == d.values.size(), "one value per frequency");
    for (std::size_t i = 1; i < d.frequency_hz.size(); ++i)
      require(d.frequency_hz[i] > d.frequency_hz[i - 1], "strictly increasing frequencies");
    const auto again = mx::readFrfCsv(mx::frfCsvString(d), "round trip", mx::FrfQuantity::Receptance);
    require(again.frequency_hz == d.frequency_hz && again.values == d.values, "CSV round trip is exact");
  } catch (const mx::FrfFileError&) {
  }
  return 0;
}
