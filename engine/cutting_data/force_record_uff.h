#pragma once
// The dynamometer record of one test cut as a universal file, the same record as the CSV's
// (force_measurement_csv.h), so that meanOverRevolutions averages both. One dataset 58 (ASCII) or 58b
// (binary) per force, as the FRF reader frames them (frf/uff_reader.h, frf/uff58_scanner.h):
//   record 6   function type 1 (time response); response direction +-1 Fx, +-2 Fy, +-3 Fz, the sign
//              multiplying the data. The file needs all three, as the CSV record needs its Fz_N column
//              (a two-component dynamometer writes a zero Fz and reads K_ac = K_ae = 0 back).
//   record 7   real ordinate (data type 2 single or 4 double), even spacing or uneven (time, force) pairs.
//   record 8   the time: specific data type 17 (time) or 0 (unknown), units s or ms (uff_units.h).
//   record 9   the force: specific data type 13 (excitation force) or 9 (reaction force), units N, kN or lbf.
// Records 10 and 11 are not read. The three forces must share their times (to 1e-9 of the record's
// length). Other datasets (151, 164, ...) and datasets 58 of another function type or a rotational
// direction are skipped. Forces on the tool, in the axes and signs of our force model; a leading UTF-8 byte
// order mark is accepted. Errors are InvalidInput "<source>: line <n>: <what>" (n 0: the whole file) or,
// inside a 58b block, "<source>: binary block of the dataset at line <n>, byte <k>: <what>".
#include <string>
#include <string_view>

#include "cutting_data/force_measurement_csv.h"

namespace mx {

// True when the first non-blank line is the "    -1" that opens a universal file's first dataset.
bool isUniversalFile(std::string_view bytes);

// The record: at least two samples, times within ±1e6 s and strictly increasing, forces finite and
// within ±1e7 N, all in SI.
ForceRecord readForceRecordUff(std::string_view bytes, const std::string& source_name);

}  // namespace mx
