#include "frf/frf_csv.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "core/invalid_input.h"
#include "frf/fortran_number.h"
#include "frf/text_lines.h"

namespace mx {
namespace {

std::string_view trimmed(std::string_view s) {
  s = s.substr(skipBlanks(s, 0));
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

struct Row {
  double f, a, b;
};

Row parseRow(const TextLine& l, const std::string& source) {
  double v[3];
  std::size_t start = 0;
  for (int k = 0; k < 3; ++k) {
    const std::size_t comma = l.text.find(',', start);
    const bool last = k == 2;
    if (last != (comma == std::string_view::npos))
      throw FrfFileError(source, l.number,
                         "expected three comma-separated numbers, found '" + std::string(l.text) + "'");
    const auto field = l.text.substr(start, last ? std::string_view::npos : comma - start);
    if (!parseFortranNumber(field, v[k]))
      throw FrfFileError(
          source, l.number,
          "expected a number in column " + std::to_string(k + 1) + ", found '" + std::string(trimmed(field)) + "'");
    start = comma + 1;
  }
  return {v[0], v[1], v[2]};
}

}  // namespace

FrfDataset readFrfCsv(std::string_view bytes, const std::string& source_name, FrfQuantity quantity) {
  TextLines lines(withoutBom(bytes));
  TextLine l;
  if (!lines.nextNonBlank(l))
    throw FrfFileError(source_name, 1,
                       "expected the CSV header '" + std::string(kFrfCsvCartesianHeader) + "' or '" +
                           std::string(kFrfCsvPolarHeader) + "', found an empty file");
  const auto header = trimmed(l.text);
  const bool polar = header == kFrfCsvPolarHeader;
  if (!polar && header != kFrfCsvCartesianHeader)
    throw FrfFileError(source_name, l.number,
                       "unknown CSV header: expected '" + std::string(kFrfCsvCartesianHeader) + "' or '" +
                           std::string(kFrfCsvPolarHeader) + "', found '" + std::string(header) + "'");
  FrfDataset d;
  d.index = 1;
  d.quantity = quantity;
  while (lines.nextNonBlank(l)) {
    const Row r = parseRow(l, source_name);
    if (!d.frequency_hz.empty() && !(r.f > d.frequency_hz.back()))
      throw FrfFileError(source_name, l.number,
                         "expected increasing frequencies, found a frequency not above the last");
    if (polar && r.a < 0.0) throw FrfFileError(source_name, l.number, "expected a magnitude >= 0");
    d.frequency_hz.push_back(r.f);
    d.values.push_back(polar ? std::polar(r.a, r.b * std::numbers::pi / 180.0) : std::complex<double>(r.a, r.b));
  }
  return d;
}

void writeFrfCsv(std::ostream& out, const FrfDataset& d) {
  if (d.frequency_hz.size() != d.values.size())
    throw InvalidInput("FRF values = " + std::to_string(d.values.size()) + " for " +
                       std::to_string(d.frequency_hz.size()) + " frequencies (must be as many)");
  out << kFrfCsvCartesianHeader << '\n';
  char buf[96];
  for (std::size_t i = 0; i < d.values.size(); ++i) {
    std::snprintf(buf, sizeof(buf), "%.17g,%.17g,%.17g\n", d.frequency_hz[i], d.values[i].real(), d.values[i].imag());
    out << buf;
  }
}

std::string frfCsvString(const FrfDataset& dataset) {
  std::ostringstream out;
  writeFrfCsv(out, dataset);
  return out.str();
}

}  // namespace mx
