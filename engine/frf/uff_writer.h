#pragma once
// Writes FRFs as universal-file datasets 58 (ASCII) and 58b (binary), readable by readUff. Both write
// records 1-11 in the fixed formats of the dataset 58 description, function type 4, positive
// directions, SI units labels (m, m/s or m/s^2 over N, Hz) and uneven abscissa, complex double data:
//   58   record 12 one point per line, frequency, real and imaginary part each E20.12 (13 significant
//        digits; the abscissa is widened from E13.5 so frequencies keep their digits too);
//   58b  identifier "58b 1 2 11 <bytes>" (little endian, IEEE), the values as 8-byte doubles in the
//        order of record 12, then the closing "    -1" directly after the block. Reads back bit for bit.
// A name longer than 80 characters is cut (record 1 is 80A1). Throws InvalidInput when a dataset's
// frequencies and values differ in length.
#include <ostream>
#include <string>
#include <vector>

#include "frf/frf_dataset.h"

namespace mx {

void writeUff58(std::ostream& out, const std::vector<FrfDataset>& datasets);
void writeUff58b(std::ostream& out, const std::vector<FrfDataset>& datasets);

std::string uff58String(const std::vector<FrfDataset>& datasets);
std::string uff58bString(const std::vector<FrfDataset>& datasets);

}  // namespace mx
