#include "cutting_data/force_record_uff.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/invalid_input.h"
#include "frf/text_lines.h"
#include "frf/uff58_scanner.h"
#include "frf/uff_units.h"

namespace mx {
namespace {

constexpr int kTimeResponse = 1;
constexpr std::array<const char*, 3> kForceNames{"Fx", "Fy", "Fz"};

[[noreturn]] void fail(const std::string& source, int line, const std::string& what) {
  throw InvalidInput(line > 0 ? source + ": line " + std::to_string(line) + ": " + what : source + ": " + what);
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.12g", v);
  return buf;
}

// One force's time series in SI; id_line 0 until its dataset is read.
struct ForceSeries {
  int id_line = 0;
  std::vector<double> t_s, f_n;
};

class ForceRecordReader {
 public:
  ForceRecordReader(std::string_view bytes, const std::string& source)
      : scanner_(withoutBom(bytes), source, "times"), source_(source) {}

  ForceRecord run() {
    Uff58Header h;
    while (scanner_.next(h)) {
      if (h.function_type != kTimeResponse || !isTranslationalUffDirection(h.response_dir)) {
        ++skipped_functions_;
        scanner_.skip(h);
        continue;
      }
      readSeries(h);
    }
    return record();
  }

 private:
  void readSeries(const Uff58Header& h) {
    const auto axis = static_cast<std::size_t>(std::abs(h.response_dir) - 1);
    ForceSeries& s = series_[axis];
    if (s.id_line != 0)
      fail(source_, h.records[6].number,
           std::string("a second time response of ") + kForceNames[axis] + " (response direction " +
               std::to_string(h.response_dir) +
               ", record 6): expected one per force, the first is the dataset at line " + std::to_string(s.id_line));
    const Uff58Record7 r7 = scanner_.record7(h);
    if (r7.complex())
      fail(source_, r7.line,
           "expected a real force (record 7 ordinate data type 2 or 4), found " + std::to_string(r7.ordinate_type));
    const double time_factor = timeFactor(h);
    const double force_factor = forceFactor(h) * (h.response_dir < 0 ? -1.0 : 1.0);
    const std::vector<double> raw = scanner_.data(h, r7);
    s.id_line = h.id_line;
    s.t_s = times(h, r7, raw, time_factor);
    s.f_n = forces(h, r7, raw, force_factor, kForceNames[axis]);
  }

  double timeFactor(const Uff58Header& h) const {
    const TextLine& r8 = h.records[8];
    const int type = scanner_.specificDataType(h, 8);
    if (type != 0 && type != 17)
      fail(source_, r8.number,
           "expected a time abscissa (record 8 specific data type 17 or 0), found " + std::to_string(type));
    const auto factor = timeUnitsToSeconds(uffUnitsLabel(r8.text));
    if (!factor)
      fail(source_, r8.number,
           "expected time units s or ms (record 8), found '" + std::string(uffUnitsLabel(r8.text)) + "'");
    return *factor;
  }

  double forceFactor(const Uff58Header& h) const {
    const TextLine& r9 = h.records[9];
    const int type = scanner_.specificDataType(h, 9);
    if (type != 13 && type != 9)
      fail(source_, r9.number,
           "expected a force (record 9 specific data type 13 excitation force or 9 reaction force), found " +
               std::to_string(type));
    const auto factor = forceUnitsToSi(uffUnitsLabel(r9.text));
    if (!factor)
      fail(source_, r9.number,
           "expected force units N, kN or lbf (record 9), found '" + std::string(uffUnitsLabel(r9.text)) + "'");
    return *factor;
  }

  // The abscissa in seconds; an even one must still increase once rounded (a large start swallows a
  // small increment).
  std::vector<double> times(const Uff58Header& h, const Uff58Record7& r7, const std::vector<double>& raw,
                            double factor) const {
    const auto n = static_cast<std::size_t>(r7.points);
    const std::size_t stride = r7.componentsPerPoint();
    std::vector<double> t(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = r7.even ? r7.x_min + static_cast<double>(i) * r7.x_increment : raw[i * stride];
      t[i] = x * factor;
      if (!(std::abs(t[i]) <= kMaxRecordTimeS))
        fail(source_, h.id_line,
             "time of point " + std::to_string(i + 1) + " = " + number(t[i]) + " s: must be within ±1e6 s");
      if (i > 0 && !(t[i] > t[i - 1]))
        fail(
            source_, r7.even ? r7.line : h.id_line,
            "time of point " + std::to_string(i + 1) + " = " + number(t[i]) + " s: must be after the previous point's");
    }
    return t;
  }

  std::vector<double> forces(const Uff58Header& h, const Uff58Record7& r7, const std::vector<double>& raw,
                             double factor, const char* name) const {
    const std::size_t stride = r7.componentsPerPoint(), first = r7.even ? 0 : 1;
    std::vector<double> f(static_cast<std::size_t>(r7.points));
    for (std::size_t i = 0; i < f.size(); ++i) {
      f[i] = raw[i * stride + first] * factor;
      if (!(std::abs(f[i]) <= kMaxTestCutForceN))
        fail(source_, h.id_line,
             std::string(name) + " of point " + std::to_string(i + 1) + " = " + number(f[i]) +
                 " N: must be within ±1e7 N");
    }
    return f;
  }

  // The three forces as one record: each present, sampled at the same times.
  ForceRecord record() const {
    for (std::size_t axis = 0; axis < 3; ++axis)
      if (series_[axis].id_line == 0)
        fail(source_, 0,
             std::string("no time response of ") + kForceNames[axis] +
                 ": expected a dataset 58 of function type 1 (record 6) with response direction +-" +
                 std::to_string(axis + 1) + "; a cut needs Fx, Fy and Fz (" + std::to_string(skipped_functions_) +
                 " dataset(s) 58 of another function type or direction skipped)");
    const ForceSeries& x = series_[0];
    for (std::size_t axis = 1; axis < 3; ++axis) requireSameTimes(series_[axis], kForceNames[axis], x);
    if (x.t_s.size() < 2) fail(source_, 0, "fewer than 2 samples: expected a record of whole revolutions");
    return {x.t_s, x.f_n, series_[1].f_n, series_[2].f_n};
  }

  void requireSameTimes(const ForceSeries& s, const char* name, const ForceSeries& x) const {
    if (s.t_s.size() != x.t_s.size())
      fail(source_, s.id_line,
           std::string(name) + " has " + std::to_string(s.t_s.size()) + " points, Fx " + std::to_string(x.t_s.size()) +
               " (dataset at line " + std::to_string(x.id_line) + "): the three forces must be sampled together");
    const double tolerance = 1e-9 * (x.t_s.back() - x.t_s.front());
    for (std::size_t i = 0; i < s.t_s.size(); ++i)
      if (!(std::abs(s.t_s[i] - x.t_s[i]) <= tolerance))
        fail(source_, s.id_line,
             "time of " + std::string(name) + " point " + std::to_string(i + 1) + " = " + number(s.t_s[i]) +
                 " s, of Fx " + number(x.t_s[i]) + " s (dataset at line " + std::to_string(x.id_line) +
                 "): the three forces must be sampled together");
  }

  Uff58Scanner scanner_;
  const std::string& source_;
  std::array<ForceSeries, 3> series_;
  int skipped_functions_ = 0;
};

}  // namespace

bool isUniversalFile(std::string_view bytes) {
  TextLines lines(withoutBom(bytes));
  TextLine line;
  return lines.nextNonBlank(line) && isUffDelimiter(line.text);
}

ForceRecord readForceRecordUff(std::string_view bytes, const std::string& source_name) {
  try {
    return ForceRecordReader(bytes, source_name).run();
  } catch (const FrfFileError& e) {
    throw InvalidInput(e.what());  // the framing's errors, as the CSV readers throw them
  }
}

}  // namespace mx
