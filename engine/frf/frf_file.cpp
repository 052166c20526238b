#include "frf/frf_file.h"

#include <fstream>

#include "core/invalid_input.h"
#include "frf/fortran_number.h"
#include "frf/frf_csv.h"
#include "frf/text_lines.h"
#include "frf/uff_reader.h"
#include "frf/uff_writer.h"

namespace mx {

std::optional<FrfFormat> detectFrfFormat(std::string_view bytes) {
  TextLines lines(withoutBom(bytes));
  TextLine l;
  if (!lines.nextNonBlank(l)) return std::nullopt;
  if (l.text.find(',') != std::string_view::npos) return FrfFormat::Csv;  // readFrfCsv names a wrong header
  if (!isUffDelimiter(l.text)) return std::nullopt;
  while (lines.nextNonBlank(l) && isUffDelimiter(l.text)) {
  }
  const auto id = tokenAt(l.text, skipBlanks(l.text, 0));
  return (id == "58b" || id == "58B") ? FrfFormat::Uff58b : FrfFormat::Uff58;
}

FrfFile readFrf(std::string_view bytes, const std::string& source_name, std::optional<FrfQuantity> csv_quantity) {
  const auto format = detectFrfFormat(bytes);
  if (!format)
    throw FrfFileError(source_name, 1,
                       "expected a universal file (a '    -1' line) or an FRF CSV (a 'frequency_Hz,...' header)");
  if (*format != FrfFormat::Csv) return readUff(bytes, source_name);
  if (!csv_quantity)
    throw FrfFileError(source_name, 1,
                       "the CSV does not say its quantity: the caller must give receptance, mobility or accelerance");
  FrfFile file;
  file.format = FrfFormat::Csv;
  file.datasets.push_back(readFrfCsv(bytes, source_name, *csv_quantity));
  return file;
}

FrfFile readFrfFile(const std::string& path, std::optional<FrfQuantity> csv_quantity) {
  std::string bytes;
  try {
    bytes = readInputFile(path, kFrfFileLimit);
  } catch (const InvalidInput& e) {
    throw FrfFileError(path, 0, e.what());
  }
  return readFrf(bytes, path, csv_quantity);
}

void writeFrfFile(const std::string& path, FrfFormat format, const std::vector<FrfDataset>& datasets) {
  if (format == FrfFormat::Csv && datasets.size() != 1)
    throw InvalidInput("CSV datasets = " + std::to_string(datasets.size()) + " (a CSV holds exactly 1 FRF)");
  std::ofstream out(path, std::ios::binary);
  if (!out) throw FrfFileError(path, 0, "cannot be written (expected a writable path)");
  switch (format) {
    case FrfFormat::Uff58:
      writeUff58(out, datasets);
      break;
    case FrfFormat::Uff58b:
      writeUff58b(out, datasets);
      break;
    case FrfFormat::Csv:
      writeFrfCsv(out, datasets.front());
      break;
  }
  out.flush();
  if (!out) throw FrfFileError(path, 0, "could not be written completely");
}

}  // namespace mx
