// libFuzzer target for readFrfCsv: any bytes either throw FrfFileError or give an FRF with as many
// values as frequencies, strictly increasing frequencies, and a CSV write that reads back bit for bit.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "frf/frf_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const auto d = mx::readFrfCsv(bytes, "fuzz.csv", mx::FrfQuantity::Receptance);
    if (d.frequency_hz.size() != d.values.size()) std::abort();
    for (std::size_t i = 1; i < d.frequency_hz.size(); ++i)
      if (!(d.frequency_hz[i] > d.frequency_hz[i - 1])) std::abort();
    const auto again = mx::readFrfCsv(mx::frfCsvString(d), "round trip", mx::FrfQuantity::Receptance);
    if (again.frequency_hz != d.frequency_hz || again.values != d.values) std::abort();
  } catch (const mx::FrfFileError&) {
  }
  return 0;
}
