// Fuzz target of the test-cut readers (cutting_data/force_measurement_csv.h): any bytes either throw
// InvalidInput or give cuts with feeds in [1e-6, 10] mm and finite forces, and a record with strictly
// increasing finite times whose mean over whole revolutions is finite.
#include <cstdint>

#include "core/invalid_input.h"
#include "cutting_data/force_measurement_csv.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using mx::fuzz::require;
  using mx::fuzz::requireFinite;
  const std::string_view bytes = mx::fuzz::bytesOf(data, size);
  try {
    for (const mx::TestCut& c : mx::readMeanForcesCsv(bytes, "fuzz.csv")) {
      require(c.feed_per_tooth_m >= 0.999e-9 && c.feed_per_tooth_m <= 10e-3, "feed per tooth in [1e-6, 10] mm");
      requireFinite(c.fx_n + c.fy_n + c.fz_n, "finite forces");
    }
  } catch (const mx::InvalidInput&) {
  }
  try {
    const mx::ForceRecord r = mx::readForceRecordCsv(bytes, "fuzz.csv");
    for (std::size_t i = 1; i < r.t_s.size(); ++i) require(r.t_s[i] > r.t_s[i - 1], "strictly increasing times");
    const mx::TestCut m = mx::meanOverRevolutions(r, 6000.0, 0.1e-3, "fuzz.csv");
    requireFinite(m.fx_n, "finite mean Fx");
    requireFinite(m.fy_n, "finite mean Fy");
    requireFinite(m.fz_n, "finite mean Fz");
  } catch (const mx::InvalidInput&) {
  }
  return 0;
}
