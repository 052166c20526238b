#pragma once
// FRFs as CSV: one header line, then one row per frequency, comma-separated. The header is exactly
//   frequency_Hz,real,imag            (Cartesian) or
//   frequency_Hz,magnitude,phase_deg  (polar: value = magnitude * exp(i * phase in radians)).
// Values are in SI units of the quantity (m/N, (m/s)/N, (m/s^2)/N); the columns cannot say which,
// so the caller passes the quantity. Frequencies must increase strictly; magnitudes are >= 0. Line
// ends "\n" or "\r\n", blanks around fields, blank lines and a UTF-8 byte order mark are accepted.
// The dataset read has index 1, x response and reference directions and nodes 0: a CSV holds one FRF
// of an axis the caller knows.
#include <ostream>
#include <string>
#include <string_view>

#include "frf/frf_dataset.h"
#include "frf/frf_file_error.h"

namespace mx {

inline constexpr std::string_view kFrfCsvCartesianHeader = "frequency_Hz,real,imag";
inline constexpr std::string_view kFrfCsvPolarHeader = "frequency_Hz,magnitude,phase_deg";

// Parses CSV bytes; throws FrfFileError (source_name, line) for an unknown header, a non-number, a
// row without three fields, a frequency not increasing or a negative magnitude.
FrfDataset readFrfCsv(std::string_view bytes, const std::string& source_name, FrfQuantity quantity);

// Writes the Cartesian form, each number with 17 significant digits (reads back bit for bit).
// Throws InvalidInput when frequencies and values differ in length.
void writeFrfCsv(std::ostream& out, const FrfDataset& dataset);
std::string frfCsvString(const FrfDataset& dataset);

}  // namespace mx
