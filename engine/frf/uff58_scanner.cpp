#include "frf/uff58_scanner.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <utility>

#include "frf/fortran_number.h"

namespace mx {
namespace {

constexpr int kHeaderRecords = 11;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.12g", v);
  return buf;
}

std::string quoted(std::string_view s) {
  return "'" + std::string(s) + "'";
}

std::string_view trim(std::string_view s) {
  return s.substr(skipBlanks(s, 0));
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

std::uint64_t load(const char* p, std::size_t size, bool big_endian) {
  std::uint64_t u = 0;
  for (std::size_t i = 0; i < size; ++i) {
    const auto byte = static_cast<std::uint64_t>(static_cast<unsigned char>(p[big_endian ? i : size - 1 - i]));
    u = (u << 8) | byte;
  }
  return u;
}

}  // namespace

std::string_view uffUnitsLabel(std::string_view record) {
  if (record.size() > 47) return trim(record.substr(47, 20));
  const auto t = tokens(record);
  return t.size() >= 6 ? t[5] : std::string_view();
}

Uff58Scanner::Uff58Scanner(std::string_view bytes, const std::string& source_name, std::string abscissa)
    : bytes_(bytes), lines_(bytes), source_(source_name), abscissa_(std::move(abscissa)) {}

bool Uff58Scanner::next(Uff58Header& h) {
  bool open = false;  // the last line was a delimiter opening a dataset
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
    ++index_;
    const auto t = tokens(id.text);
    h = Uff58Header();
    h.binary = t[0] == "58b" || t[0] == "58B";
    if (t[0] != "58" && !h.binary) {
      ++skipped_datasets_;
      skipToDelimiter();
      continue;
    }
    h.index = index_;
    h.id_line = id.number;
    if (h.binary) readBinaryIdentifier(id, t, h);
    for (int k = 1; k <= kHeaderRecords; ++k) h.records[static_cast<std::size_t>(k)] = headerRecord(k, id.number);
    h.name = std::string(trim(h.records[1].text));
    readRecord6(h);
    return true;
  }
  return false;
}

void Uff58Scanner::skipToDelimiter() {
  TextLine l;
  while (lines_.next(l))
    if (isUffDelimiter(l.text)) return;
}

TextLine Uff58Scanner::headerRecord(int record, int id_line) {
  TextLine l;
  if (!lines_.next(l))
    throw error(lines_.lineNumber() + 1, "expected record " + std::to_string(record) + " of the dataset 58 at line " +
                                             std::to_string(id_line) + ", found the end of the file (truncated)");
  return l;
}

int Uff58Scanner::integer(std::string_view token, const TextLine& l, const std::string& what) const {
  double v = 0.0;
  if (!parseFortranNumber(token, v) || v != std::floor(v) || std::abs(v) > 2e9)
    throw error(l.number, "expected an integer " + what + ", found " + quoted(token));
  return static_cast<int>(v);
}

// Record 6 (format 2(I5,I10),2(1X,10A1,I10,I4)): a full 80-column record is read by its columns (the
// entity names may be blank or hold blanks); a shorter, free-format one must have its ten fields.
void Uff58Scanner::readRecord6(Uff58Header& h) const {
  const TextLine& l = h.records[6];
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

Uff58Record7 Uff58Scanner::record7(const Uff58Header& h) const {
  const TextLine& l = h.records[7];
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
  Uff58Record7 r;
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
    throw error(l.number, "expected an abscissa increment > 0 (" + abscissa_ + " increasing, record 7)");
  return r;
}

int Uff58Scanner::specificDataType(const Uff58Header& h, int record) const {
  const TextLine& l = h.records[static_cast<std::size_t>(record)];
  const auto t = tokens(l.text);
  if (t.empty()) throw error(l.number, "expected record " + std::to_string(record) + ", found a blank line");
  return integer(t[0], l, "specific data type");
}

// Parses "58b <order> <format> <lines> <bytes> ..." into the block size; checks what we can read.
void Uff58Scanner::readBinaryIdentifier(const TextLine& id, const std::vector<std::string_view>& t,
                                        Uff58Header& h) const {
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
  h.big_endian = order == 2;
  h.block_bytes = static_cast<std::size_t>(bytes);
}

void Uff58Scanner::requireBlock(const Uff58Header& h) const {
  if (h.block_bytes > lines_.remaining())
    throw FrfFileError(
        source_, h.id_line, lines_.remaining(),
        "truncated binary block: expected " + std::to_string(h.block_bytes) + " bytes, found the end of the file");
}

void Uff58Scanner::skip(const Uff58Header& h) {
  if (!h.binary) return skipToDelimiter();
  requireBlock(h);
  lines_.skip(h.block_bytes);
  closeDataset(h.id_line);
}

// After the data: "-1" (or the end of the file).
void Uff58Scanner::closeDataset(int id_line) {
  TextLine l;
  if (!lines_.nextNonBlank(l)) return;
  if (!isUffDelimiter(l.text))
    throw error(l.number, "expected '    -1' closing the dataset at line " + std::to_string(id_line) + ", found " +
                              quoted(l.text));
}

std::string Uff58Scanner::countText(const Uff58Record7& r7) const {
  return std::to_string(r7.values()) + " values (" + std::to_string(r7.points) + " points, record 7 at line " +
         std::to_string(r7.line) + ")";
}

std::vector<double> Uff58Scanner::data(const Uff58Header& h, const Uff58Record7& r7) {
  std::vector<double> raw = h.binary ? readBinary(h, r7) : readAscii(r7);
  closeDataset(h.id_line);
  return raw;
}

// Record 12 as text, up to the closing delimiter (which is put back for closeDataset).
std::vector<double> Uff58Scanner::readAscii(const Uff58Record7& r7) {
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
          throw error(l.number,
                      "expected increasing " + abscissa_ + ", found " + number(v) + " after " + number(last_x));
        last_x = v;
      }
      raw.push_back(v);
    }
  }
}

std::vector<double> Uff58Scanner::readBinary(const Uff58Header& h, const Uff58Record7& r7) {
  const std::size_t size = r7.doublePrecision() ? 8 : 4;
  const std::size_t expected = r7.values() * size;
  const std::size_t start = lines_.position();
  requireBlock(h);
  if (h.block_bytes != expected)
    throw FrfFileError(source_, h.id_line, 0,
                       "point count does not match the header: the block holds " + std::to_string(h.block_bytes) +
                           " bytes, expected " + std::to_string(expected) + " for " + countText(r7));
  const char* p = bytes_.data() + start;
  const std::size_t stride = r7.componentsPerPoint();
  std::vector<double> raw(r7.values());
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const std::uint64_t u = load(p + i * size, size, h.big_endian);
    const double v =
        size == 8 ? std::bit_cast<double>(u) : static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(u)));
    if (!std::isfinite(v)) throw FrfFileError(source_, h.id_line, i * size, "expected a finite value");
    if (!r7.even && i % stride == 0 && i > 0 && !(v > raw[i - stride]))
      throw FrfFileError(source_, h.id_line, i * size, "expected increasing " + abscissa_);
    raw[i] = v;
  }
  lines_.skip(h.block_bytes);
  return raw;
}

}  // namespace mx
