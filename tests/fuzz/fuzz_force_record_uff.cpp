// Fuzz target of readForceRecordUff (a test cut's dynamometer record as universal-file datasets 58/58b of
// function type 1): any bytes either throw InvalidInput or give a record of at least two samples, one
// value of each force per time, times finite, within ±1e6 s and strictly increasing, forces finite and
// within ±1e7 N; written as a CSV record, it reads back bit for bit and averages to the same means.
#include <bit>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "core/invalid_input.h"
#include "cutting_data/force_record_uff.h"
#include "fuzz_check.h"

namespace {

using mx::fuzz::require;

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  return true;
}

void checkPromises(const mx::ForceRecord& r) {
  const std::size_t n = r.t_s.size();
  require(n >= 2 && r.fx_n.size() == n && r.fy_n.size() == n && r.fz_n.size() == n,
          "at least two samples, one value of each force per time");
  for (std::size_t i = 0; i < n; ++i) {
    require(std::abs(r.t_s[i]) <= mx::kMaxRecordTimeS, "finite times within 1e6 s");
    require(i == 0 || r.t_s[i] > r.t_s[i - 1], "strictly increasing times");
    for (double f : {r.fx_n[i], r.fy_n[i], r.fz_n[i]})
      require(std::abs(f) <= mx::kMaxTestCutForceN, "finite forces within 1e7 N");
  }
}

std::string csvOf(const mx::ForceRecord& r) {
  std::string csv = "time_s,Fx_N,Fy_N,Fz_N\n";
  char line[128];
  for (std::size_t i = 0; i < r.t_s.size(); ++i) {
    std::snprintf(line, sizeof(line), "%.17g,%.17g,%.17g,%.17g\n", r.t_s[i], r.fx_n[i], r.fy_n[i], r.fz_n[i]);
    csv += line;
  }
  return csv;
}

// The mean of a record that spans a revolution at `rpm`, or nullopt when it is too short.
std::optional<mx::TestCut> mean(const mx::ForceRecord& r, double rpm) {
  try {
    return mx::meanOverRevolutions(r, rpm, 0.1e-3, "fuzz");
  } catch (const mx::InvalidInput&) {
    return std::nullopt;
  }
}

mx::ForceRecord csvRoundTrip(const mx::ForceRecord& r) {
  try {
    return mx::readForceRecordCsv(csvOf(r), "round trip");
  } catch (const mx::InvalidInput&) {
    mx::fuzz::brokenPromise("a CSV record write reads back");
  }
}

void checkCsvRoundTrip(const mx::ForceRecord& r) {
  const mx::ForceRecord again = csvRoundTrip(r);
  require(sameBits(r.t_s, again.t_s) && sameBits(r.fx_n, again.fx_n) && sameBits(r.fy_n, again.fy_n) &&
              sameBits(r.fz_n, again.fz_n),
          "a CSV record write reads back bit for bit");
  const double rpm = 60.0 / (r.t_s.back() - r.t_s.front());  // one revolution: the whole record
  const auto a = mean(r, rpm), b = mean(again, rpm);
  require(a.has_value() == b.has_value(), "the UFF and CSV records both span a revolution or neither");
  if (!a) return;
  mx::fuzz::requireFinite(a->fx_n + a->fy_n + a->fz_n, "finite means");
  require(a->fx_n == b->fx_n && a->fy_n == b->fy_n && a->fz_n == b->fz_n, "the same means as the CSV record");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mx::ForceRecord r;
  try {
    r = mx::readForceRecordUff(mx::fuzz::bytesOf(data, size), "fuzz.unv");
  } catch (const mx::InvalidInput&) {
    return 0;
  }
  checkPromises(r);
  checkCsvRoundTrip(r);
  return 0;
}
