#pragma once
// FRF files by path: the format is detected from the content, not the name. A universal file starts
// (after blank lines) with the "    -1" delimiter, its first dataset's identifier saying 58b or else
// 58; a CSV's first line holds a comma (frf_csv.h then requires one of its two headers).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/input_file.h"
#include "frf/frf_dataset.h"
#include "frf/frf_file_error.h"

namespace mx {

// The detected format of the bytes; nullopt when they are neither a universal file nor an FRF CSV.
std::optional<FrfFormat> detectFrfFormat(std::string_view bytes);

// Parses in-memory bytes of any FRF format. csv_quantity is what a CSV's values are (the columns do not
// say); FrfFileError "... the CSV does not say its quantity ..." when a CSV comes without it.
FrfFile readFrf(std::string_view bytes, const std::string& source_name, std::optional<FrfQuantity> csv_quantity);

// A tap-test file: far above any measurement (a few thousand lines per FRF), far below memory limits.
inline constexpr InputFileLimit kFrfFileLimit{64 * kMegabyte, "an FRF file"};

// Reads the file at path (FrfFileError naming the path when it cannot be read, is over kFrfFileLimit or
// is not a regular file) and parses it as readFrf.
FrfFile readFrfFile(const std::string& path, std::optional<FrfQuantity> csv_quantity);

// Writes datasets to path in the format; a CSV takes exactly one dataset. Throws InvalidInput for a
// CSV of another count and FrfFileError when the file cannot be written.
void writeFrfFile(const std::string& path, FrfFormat format, const std::vector<FrfDataset>& datasets);

}  // namespace mx
