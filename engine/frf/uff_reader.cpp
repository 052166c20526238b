#include "frf/uff_reader.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include "frf/fortran_number.h"
#include "frf/text_lines.h"
#include "frf/uff_units.h"

namespace mx {
namespace {

constexpr int kFrfFunctionType = 4;
constexpr int kHeaderRecords = 11;

struct Record7 {
  int ordinate_type = 0;
  int points = 0;
  bool even = true;
  double x_min = 0.0;
  double x_increment = 0.0;
  int line = 0;

  bool complex() const { return ordinate_type == 5 || ordinate_type == 6; }
  bool doublePrecision() const { return ordinate_type == 4 || ordinate_type == 6; }
  std::size_t componentsPerPoint() const { return (complex() ? 2u : 1u) + (even ? 0u : 1u); }
  std::size_t values() const { return static_cast<std::size_t>(points) * componentsPerPoint(); }
};

struct Header {
  std::string name;
  int function_type = 0;
  int response_node = 0, response_dir = 0, reference_node = 0, reference_dir = 0;
  Record7 r7;
  FrfQuantity quantity = FrfQuantity::Receptance;
  double frequency_factor = 1.0;
  double value_factor = 1.0;  // numerator to SI / denominator to SI, times the direction signs
};

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.12g", v);
  return buf;
}

std::string quoted(std::string_view s) {
  return "'" + std::string(s) + "'";
}

std::string_view trim(std::string_view s) {
  const std::size_t b = skipBlanks(s, 0);
  return s.substr(b);
}

std::vector<std::string_view> tokens(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t p = skipBlanks(s, 0);
  while (p < s.size()) {
    out.push_back(tokenAt(s, p));
    p = skipBlanks(s, p + out.back().size());
  }
  return out;
}

// Records 8-11 (format I10,3I5,2(1X,20A1)): the units label sits in columns 48-67; a shorter line is
// read as blank-separated "type exponents... axis-label units-label".
std::string_view unitsLabel(std::string_view line) {
  if (line.size() > 47) return trim(line.substr(47, 20));
  const auto t = tokens(line);
  return t.size() >= 6 ? t[5] : std::string_view();
}

class UffParser {
 public:
  UffParser(std::string_view bytes, const std::string& source) : bytes_(bytes), lines_(bytes), source_(source) {}

  FrfFile run() {
    FrfFile file;
    bool first_58 = true;
    bool open = false;  // the last line was a delimiter opening a dataset
    int index = 0;
    TextLine id;
    while (lines_.nextNonBlank(id)) {
      if (!open) {
        if (!isUffDelimiter(id.text))
          throw error(id.number, "expected '    -1' opening a dataset, found " + quoted(id.text));
        open = true;
        continue;
      }
      if (isUffDelimiter(id.text)) continue;  // an empty dataset
      open = false;
      ++index;
      const auto t = tokens(id.text);
      const bool binary = t[0] == "58b" || t[0] == "58B";
      if (t[0] != "58" && !binary) {
        ++file.skipped_datasets;
        skipToDelimiter();
        continue;
      }
      if (first_58) file.format = binary ? FrfFormat::Uff58b : FrfFormat::Uff58;
      first_58 = false;
      readDataset(id, t, binary, index, file);
    }
    return file;
  }

 private:
  FrfFileError error(int line, const std::string& expected) const { return FrfFileError(source_, line, expected); }

  void skipToDelimiter() {
    TextLine l;
    while (lines_.next(l))
      if (isUffDelimiter(l.text)) return;
  }

  TextLine headerRecord(int record, int id_line) {
    TextLine l;
    if (!lines_.next(l))
      throw error(lines_.lineNumber() + 1, "expected record " + std::to_string(record) + " of the dataset 58 at line " +
                                               std::to_string(id_line) + ", found the end of the file (truncated)");
    return l;
  }

  int integer(std::string_view token, const TextLine& l, const char* what) const {
    double v = 0.0;
    if (!parseFortranNumber(token, v) || v != std::floor(v) || std::abs(v) > 2e9)
      throw error(l.number, std::string("expected an integer ") + what + ", found " + quoted(token));
    return static_cast<int>(v);
  }

  // Record 6 (format 2(I5,I10),2(1X,10A1,I10,I4)): a full 80-column record is read by its columns (the
  // entity names may be blank or hold blanks); a shorter, free-format one must have its ten fields.
  void readRecord6(const TextLine& l, Header& h) const {
    if (l.text.size() == 80) {
      auto field = [&](std::size_t from, std::size_t width) { return trim(l.text.substr(from, width)); };
      h.function_type = integer(field(0, 5), l, "function type (record 6, columns 1-5)");
      h.response_node = integer(field(41, 10), l, "response node (record 6, columns 42-51)");
      h.response_dir = integer(field(51, 4), l, "response direction (record 6, columns 52-55)");
      h.reference_node = integer(field(66, 10), l, "reference node (record 6, columns 67-76)");
      h.reference_dir = integer(field(76, 4), l, "reference direction (record 6, columns 77-80)");
      return;
    }
    const auto t = tokens(l.text);
    if (t.size() != 10)
      throw error(l.number,
                  "expected record 6: function type, ids, and entity name, node, direction of response "
                  "and reference");
    h.function_type = integer(t[0], l, "function type (record 6)");
    h.response_node = integer(t[5], l, "response node (record 6)");
    h.response_dir = integer(t[6], l, "response direction (record 6)");
    h.reference_node = integer(t[8], l, "reference node (record 6)");
    h.reference_dir = integer(t[9], l, "reference direction (record 6)");
  }

  Record7 readRecord7(const TextLine& l) const {
    std::vector<double> v;
    for (std::size_t p = skipBlanks(l.text, 0); p < l.text.size(); p = skipBlanks(l.text, p)) {
      double x = 0.0;
      if (!scanFortranNumber(l.text, p, x))
        throw error(l.number, "expected a number in record 7, found " + quoted(tokenAt(l.text, p)));
      v.push_back(x);
    }
    if (v.size() < 5)
      throw error(l.number, "expected record 7: data type, points, spacing, abscissa minimum and increment");
    auto whole = [&](double x, const char* what) {
      if (x != std::floor(x) || std::abs(x) > 2e9)
        throw error(l.number, std::string("expected an integer ") + what + " in record 7");
      return static_cast<int>(x);
    };
    Record7 r;
    r.line = l.number;
    r.ordinate_type = whole(v[0], "ordinate data type");
    r.points = whole(v[1], "number of points");
    const int spacing = whole(v[2], "abscissa spacing");
    r.x_min = v[3];
    r.x_increment = v[4];
    if (r.ordinate_type != 2 && r.ordinate_type != 4 && r.ordinate_type != 5 && r.ordinate_type != 6)
      throw error(l.number,
                  "expected ordinate data type 2, 4, 5 or 6 (record 7), found " + std::to_string(r.ordinate_type));
    if (r.points < 1) throw error(l.number, "expected a number of points >= 1 (record 7)");
    if (spacing != 0 && spacing != 1)
      throw error(l.number,
                  "expected abscissa spacing 0 (uneven) or 1 (even) (record 7), found " + std::to_string(spacing));
    r.even = spacing == 1;
    if (r.even && r.points > 1 && !(r.x_increment > 0.0))
      throw error(l.number, "expected an abscissa increment > 0 (frequencies increasing, record 7)");
    return r;
  }

  int specificType(const TextLine& l, int record) const {
    const auto t = tokens(l.text);
    if (t.empty()) throw error(l.number, "expected record " + std::to_string(record) + ", found a blank line");
    return integer(t[0], l, "specific data type");
  }

  void readUnits(const TextLine& r8, const TextLine& r9, const TextLine& r10, Header& h) const {
    const int abscissa = specificType(r8, 8);
    if (abscissa != 0 && abscissa != 18)
      throw error(r8.number,
                  "expected a frequency abscissa (record 8 type 18 or 0), found " + std::to_string(abscissa));
    const auto hz = frequencyUnitsToHz(unitsLabel(r8.text));
    if (!hz) throw error(r8.number, "expected abscissa units Hz (record 8), found " + quoted(unitsLabel(r8.text)));
    h.frequency_factor = *hz;

    switch (specificType(r9, 9)) {
      case 8:
        h.quantity = FrfQuantity::Receptance;
        break;
      case 11:
        h.quantity = FrfQuantity::Mobility;
        break;
      case 12:
        h.quantity = FrfQuantity::Accelerance;
        break;
      default:
        throw error(r9.number,
                    "expected ordinate numerator type 8 (displacement), 11 (velocity) or 12 (acceleration) (record 9)");
    }
    const auto num = numeratorUnitsToSi(h.quantity, unitsLabel(r9.text));
    if (!num)
      throw error(r9.number, "expected " + std::string(frfQuantityName(h.quantity)) +
                                 " numerator units (record 9, see uff_units.h), found " + quoted(unitsLabel(r9.text)));
    const int denominator = specificType(r10, 10);
    if (denominator != 13)
      throw error(r10.number,
                  "FRF not in force units: expected ordinate denominator type 13 (force) (record 10), found " +
                      std::to_string(denominator));
    const auto force = forceUnitsToSi(unitsLabel(r10.text));
    if (!force)
      throw error(r10.number,
                  "FRF not in force units: expected N, kN or lbf (record 10), found " + quoted(unitsLabel(r10.text)));
    h.value_factor = *num / *force;
  }

  // Parses "58b <order> <format> <lines> <bytes> ..." into the block size; checks what we can read.
  std::size_t binaryBlockSize(const TextLine& id, const std::vector<std::string_view>& t, bool& big_endian) const {
    if (t.size() < 5) throw error(id.number, "expected '58b <byte order> <float format> 11 <bytes>' identifier");
    const int order = integer(t[1], id, "byte ordering (58b)");
    const int format = integer(t[2], id, "floating point format (58b)");
    const int ascii = integer(t[3], id, "number of ASCII lines (58b)");
    double bytes = 0.0;
    if (!parseFortranNumber(t[4], bytes) || bytes < 0 || bytes != std::floor(bytes) || bytes > 1e15)
      throw error(id.number, "expected the number of binary bytes (58b), found " + quoted(t[4]));
    if (order != 1 && order != 2)
      throw error(id.number,
                  "expected byte ordering 1 (little endian) or 2 (big endian) (58b), found " + std::to_string(order));
    if (format != 2)
      throw error(id.number, "expected floating point format 2 (IEEE 754) (58b), found " + std::to_string(format));
    if (ascii != kHeaderRecords)
      throw error(id.number, "expected 11 ASCII header lines (58b), found " + std::to_string(ascii));
    big_endian = order == 2;
    return static_cast<std::size_t>(bytes);
  }

  static bool translational(int dir) { return dir != 0 && std::abs(dir) <= 3; }

  void readDataset(const TextLine& id, const std::vector<std::string_view>& t, bool binary, int index, FrfFile& file) {
    bool big_endian = false;
    const std::size_t block = binary ? binaryBlockSize(id, t, big_endian) : 0;
    TextLine r[kHeaderRecords + 1];
    for (int k = 1; k <= kHeaderRecords; ++k) r[k] = headerRecord(k, id.number);
    Header h;
    h.name = std::string(trim(r[1].text));
    readRecord6(r[6], h);
    if (h.function_type != kFrfFunctionType || !translational(h.response_dir) || !translational(h.reference_dir)) {
      ++file.skipped_functions;
      skipData(binary, block, id.number);
      return;
    }
    h.r7 = readRecord7(r[7]);
    readUnits(r[8], r[9], r[10], h);
    if ((h.response_dir < 0) != (h.reference_dir < 0)) h.value_factor = -h.value_factor;
    const std::vector<double> raw = binary ? readBinary(h.r7, block, big_endian, id.number) : readAscii(h.r7);
    closeDataset(id.number);
    file.datasets.push_back(makeDataset(h, raw, index, id.number));
  }

  void skipData(bool binary, std::size_t block, int id_line) {
    if (!binary) return skipToDelimiter();
    if (block > lines_.remaining())
      throw FrfFileError(
          source_, id_line, lines_.remaining(),
          "truncated binary block: expected " + std::to_string(block) + " bytes, found the end of the file");
    lines_.skip(block);
    closeDataset(id_line);
  }

  // After the data: "-1" (or the end of the file).
  void closeDataset(int id_line) {
    TextLine l;
    if (!lines_.nextNonBlank(l)) return;
    if (!isUffDelimiter(l.text))
      throw error(l.number, "expected '    -1' closing the dataset at line " + std::to_string(id_line) + ", found " +
                                quoted(l.text));
  }

  std::string countText(const Record7& r7) const {
    return std::to_string(r7.values()) + " values (" + std::to_string(r7.points) + " points, record 7 at line " +
           std::to_string(r7.line) + ")";
  }

  // Record 12 as text, up to the closing delimiter (which is put back for closeDataset).
  std::vector<double> readAscii(const Record7& r7) {
    const std::size_t expected = r7.values();
    const std::size_t stride = r7.componentsPerPoint();
    std::vector<double> raw;
    raw.reserve(std::min(expected, lines_.remaining() / 2));  // a value takes 2 bytes or more
    double last_x = 0.0;
    TextLine l;
    while (true) {
      if (!lines_.next(l)) {
        if (raw.size() == expected) return raw;
        throw error(lines_.lineNumber(), "truncated data: expected " + countText(r7) + ", found " +
                                             std::to_string(raw.size()) + " before the end of the file");
      }
      if (isUffDelimiter(l.text)) {
        if (raw.size() != expected)
          throw error(l.number, "point count does not match the header: expected " + countText(r7) + ", found " +
                                    std::to_string(raw.size()));
        lines_.putBack();
        return raw;
      }
      for (std::size_t p = skipBlanks(l.text, 0); p < l.text.size(); p = skipBlanks(l.text, p)) {
        double v = 0.0;
        if (!scanFortranNumber(l.text, p, v))
          throw error(l.number, "expected a number in record 12, found " + quoted(tokenAt(l.text, p)));
        if (raw.size() == expected)
          throw error(l.number, "point count does not match the header: more than the expected " + countText(r7));
        if (!r7.even && raw.size() % stride == 0) {
          if (!raw.empty() && !(v > last_x))
            throw error(l.number, "expected increasing frequencies, found " + number(v) + " after " + number(last_x));
          last_x = v;
        }
        raw.push_back(v);
      }
    }
  }

  static std::uint64_t load(const char* p, std::size_t size, bool big_endian) {
    std::uint64_t u = 0;
    for (std::size_t i = 0; i < size; ++i) {
      const auto byte = static_cast<std::uint64_t>(static_cast<unsigned char>(p[big_endian ? i : size - 1 - i]));
      u = (u << 8) | byte;
    }
    return u;
  }

  std::vector<double> readBinary(const Record7& r7, std::size_t block, bool big_endian, int id_line) {
    const std::size_t size = r7.doublePrecision() ? 8 : 4;
    const std::size_t expected = r7.values() * size;
    const std::size_t start = lines_.position();
    if (block > lines_.remaining())
      throw FrfFileError(
          source_, id_line, lines_.remaining(),
          "truncated binary block: expected " + std::to_string(block) + " bytes, found the end of the file");
    if (block != expected)
      throw FrfFileError(source_, id_line, 0,
                         "point count does not match the header: the block holds " + std::to_string(block) +
                             " bytes, expected " + std::to_string(expected) + " for " + countText(r7));
    const char* p = bytes_.data() + start;
    const std::size_t stride = r7.componentsPerPoint();
    std::vector<double> raw(r7.values());
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const std::uint64_t u = load(p + i * size, size, big_endian);
      const double v = size == 8 ? std::bit_cast<double>(u)
                                 : static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(u)));
      if (!std::isfinite(v)) throw FrfFileError(source_, id_line, i * size, "expected a finite value");
      if (!r7.even && i % stride == 0 && i > 0 && !(v > raw[i - stride]))
        throw FrfFileError(source_, id_line, i * size, "expected increasing frequencies");
      raw[i] = v;
    }
    lines_.skip(block);
    return raw;
  }

  static FrfDirection axis(int dir) { return static_cast<FrfDirection>(std::abs(dir) - 1); }

  // The dataset from record 12's values; an even abscissa must still increase once rounded (a large
  // minimum swallows a small increment) and the values must stay finite in SI units.
  FrfDataset makeDataset(const Header& h, const std::vector<double>& raw, int index, int id_line) const {
    FrfDataset d;
    d.index = index;
    d.name = h.name;
    d.response_node = h.response_node;
    d.reference_node = h.reference_node;
    d.response_direction = axis(h.response_dir);
    d.reference_direction = axis(h.reference_dir);
    d.quantity = h.quantity;
    const auto n = static_cast<std::size_t>(h.r7.points);
    const std::size_t stride = h.r7.componentsPerPoint();
    const std::size_t first = h.r7.even ? 0 : 1;
    d.frequency_hz.resize(n);
    d.values.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double* v = raw.data() + i * stride;
      const double x = h.r7.even ? h.r7.x_min + static_cast<double>(i) * h.r7.x_increment : v[0];
      d.frequency_hz[i] = x * h.frequency_factor;
      if (!std::isfinite(d.frequency_hz[i]) || (i > 0 && !(d.frequency_hz[i] > d.frequency_hz[i - 1])))
        throw error(h.r7.line, "expected increasing finite frequencies: abscissa minimum + increment x " +
                                   std::to_string(i) + " does not increase (record 7)");
      const double im = h.r7.complex() ? v[first + 1] : 0.0;
      d.values[i] = std::complex<double>(v[first], im) * h.value_factor;
      if (!std::isfinite(d.values[i].real()) || !std::isfinite(d.values[i].imag()))
        throw error(id_line,
                    "expected values that are finite in SI units, point " + std::to_string(i + 1) + " overflows");
    }
    return d;
  }

  std::string_view bytes_;
  TextLines lines_;
  const std::string& source_;
};

}  // namespace

FrfFile readUff(std::string_view bytes, const std::string& source_name) {
  return UffParser(bytes, source_name).run();
}

}  // namespace mx
