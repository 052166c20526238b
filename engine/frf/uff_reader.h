#pragma once
// Reads the FRFs of a universal file: datasets 58 (ASCII) and 58b (binary), as described by the UC-SDRL
// pages on dataset 58 and the binary 58 format.
//   Records 1-5: ID lines (record 1 becomes the name). Record 6: function type (only 4, FRF, is read;
//   others are skipped and counted), response node and direction, reference node and direction; the
//   directions must be translational (+-1 x, +-2 y, +-3 z; others are skipped and counted) and the
//   product of their signs multiplies the data. Record 7: ordinate data type (2 real single, 4 real
//   double, 5 complex single, 6 complex double), number of points, abscissa spacing (1 even: minimum
//   and increment; 0 uneven: (x, y) pairs in record 12). Record 8: abscissa, frequency in Hz. Record 9:
//   numerator, specific data type 8 displacement, 11 velocity or 12 acceleration. Record 10:
//   denominator, specific data type 13 (excitation force). The units labels of records 8-10 scale the
//   values to SI (uff_units.h). Record 12: the data, parsed by blanks with touching fixed fields and
//   Fortran D exponents accepted (fortran_number.h).
//   58b: the identifier line "58b <byte order 1 little / 2 big endian> <2 IEEE> <11 ASCII lines>
//   <bytes of binary data>" is followed by records 1-11 as text and the data as raw values in the
//   order of record 12; the abscissa of uneven data has the precision of the ordinate.
// Other datasets (15, 151, 164, ...) are skipped and counted. Line ends "\n" or "\r\n", trailing
// blanks and a missing final newline or final "-1" are accepted.
#include <string>
#include <string_view>

#include "frf/frf_dataset.h"
#include "frf/frf_file_error.h"

namespace mx {

// Parses the bytes of a universal file; `source_name` names it in errors. Throws FrfFileError for a
// malformed 58/58b dataset (truncated block, non-number, point count not matching record 7, frequency
// not increasing, FRF not per unit force, unrecognised units, unsupported data type). format is
// Uff58b when the first 58-family dataset is binary.
FrfFile readUff(std::string_view bytes, const std::string& source_name);

}  // namespace mx
