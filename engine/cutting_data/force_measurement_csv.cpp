#include "cutting_data/force_measurement_csv.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "core/invalid_input.h"
#include "frf/text_lines.h"

namespace mx {
namespace {

[[noreturn]] void fail(const std::string& source, int line, const std::string& what) {
  throw InvalidInput(source + ": line " + std::to_string(line) + ": " + what);
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i)
    if (i == line.size() || line[i] == ',') {
      out.push_back(trimmed(line.substr(start, i - start)));
      start = i + 1;
    }
  return out;
}

double number(std::string_view text, const std::string& source, int line, const char* column) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v))
    fail(source, line, std::string(column) + " = '" + std::string(text.substr(0, 40)) + "': expected a finite number");
  return v;
}

double force(std::string_view text, const std::string& source, int line, const char* column) {
  const double f = number(text, source, line, column);
  if (std::abs(f) > kMaxTestCutForceN)
    fail(source, line, std::string(column) + " = " + std::string(text.substr(0, 40)) + ": must be within ±1e7 N");
  return f;
}

// Rows of four numbers after the expected header; `row` gets (line number, the four fields).
template <typename Row>
void readRows(std::string_view bytes, const std::string& source, std::string_view header, Row row) {
  TextLines lines(withoutBom(bytes));
  TextLine line;
  if (!lines.nextNonBlank(line)) fail(source, 0, "the file is empty: expected the header " + std::string(header));
  if (trimmed(line.text) != header) {
    std::string h;
    for (std::string_view f : fields(line.text)) {
      if (!h.empty()) h += ',';
      h.append(f);
    }
    if (h != header)
      fail(source, line.number,
           "header '" + std::string(line.text.substr(0, 80)) + "': expected " + std::string(header));
  }
  while (lines.nextNonBlank(line)) {
    const std::vector<std::string_view> f = fields(line.text);
    if (f.size() != 4)
      fail(source, line.number, std::to_string(f.size()) + " fields: expected 4 (" + std::string(header) + ")");
    row(line.number, f);
  }
}

}  // namespace

bool isForceRecordCsv(std::string_view bytes) {
  TextLines lines(withoutBom(bytes));
  TextLine line;
  return lines.nextNonBlank(line) && fields(line.text).front() == "time_s";
}

std::vector<TestCut> readMeanForcesCsv(std::string_view bytes, const std::string& source) {
  std::vector<TestCut> cuts;
  readRows(bytes, source, kMeanForcesHeader, [&](int n, const std::vector<std::string_view>& f) {
    const double feed_mm = number(f[0], source, n, "feed_mm_per_tooth");
    if (!(feed_mm >= 1e-6 && feed_mm <= 10.0))
      fail(source, n, "feed_mm_per_tooth = " + std::string(f[0]) + ": must be in [1e-06, 10] mm");
    cuts.push_back({feed_mm / 1000.0, force(f[1], source, n, "Fx_N"), force(f[2], source, n, "Fy_N"),
                    force(f[3], source, n, "Fz_N")});
  });
  if (cuts.empty()) fail(source, 0, "no cut: expected one row per test cut after the header");
  return cuts;
}

ForceRecord readForceRecordCsv(std::string_view bytes, const std::string& source) {
  ForceRecord r;
  readRows(bytes, source, kForceRecordHeader, [&](int n, const std::vector<std::string_view>& f) {
    const double t = number(f[0], source, n, "time_s");
    if (std::abs(t) > kMaxRecordTimeS) fail(source, n, "time_s = " + std::string(f[0]) + ": must be within ±1e6 s");
    if (!r.t_s.empty() && !(t > r.t_s.back()))
      fail(source, n, "time_s = " + std::string(f[0]) + ": must be after the previous sample's");
    r.t_s.push_back(t);
    r.fx_n.push_back(force(f[1], source, n, "Fx_N"));
    r.fy_n.push_back(force(f[2], source, n, "Fy_N"));
    r.fz_n.push_back(force(f[3], source, n, "Fz_N"));
  });
  if (r.t_s.size() < 2) fail(source, 0, "fewer than 2 samples: expected a record of whole revolutions");
  return r;
}

TestCut meanOverRevolutions(const ForceRecord& r, double rpm, double feed_per_tooth_m, const std::string& source) {
  if (!(rpm > 0.0 && rpm <= 1e6))
    throw InvalidInput(source + ": spindle speed = " + std::to_string(rpm) + " rpm: must be in (0, 1e6]");
  const double revolution = 60.0 / rpm, t0 = r.t_s.front(), span = r.t_s.back() - t0;
  const double revolutions = std::floor(span / revolution * (1.0 + 1e-12));
  if (revolutions < 1.0) {
    std::ostringstream os;
    os << source << ": the record lasts " << span << " s, less than one revolution (" << revolution << " s at " << rpm
       << " rpm): the mean force needs whole revolutions";
    throw InvalidInput(os.str());
  }
  const double t_end = std::min(r.t_s.back(), t0 + revolutions * revolution);
  TestCut mean{feed_per_tooth_m, 0.0, 0.0, 0.0};
  for (std::size_t i = 1; i < r.t_s.size() && r.t_s[i - 1] < t_end; ++i) {
    const double a = r.t_s[i - 1], b = std::min(r.t_s[i], t_end);
    const double w = (b - a) / (r.t_s[i] - a);  // the share of the interval inside the window
    auto area = [&](const std::vector<double>& f) {
      const double fb = f[i - 1] + w * (f[i] - f[i - 1]);
      return 0.5 * (f[i - 1] + fb) * (b - a);
    };
    mean.fx_n += area(r.fx_n), mean.fy_n += area(r.fy_n), mean.fz_n += area(r.fz_n);
  }
  const double window = t_end - t0;
  mean.fx_n /= window, mean.fy_n /= window, mean.fz_n /= window;
  return mean;
}

}  // namespace mx
