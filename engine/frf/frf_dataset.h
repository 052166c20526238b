#pragma once
// Tap-test frequency response functions as read from or written to a file. Values are in SI units of
// their quantity (m/N, (m/s)/N, (m/s^2)/N) and frequencies in Hz; the sign of the file's directions is
// already applied, so every FRF is stated for positive response and reference axes.
#include <complex>
#include <string>
#include <string_view>
#include <vector>

namespace mx {

enum class FrfFormat { Uff58, Uff58b, Csv };
// What the FRF's numerator measures per newton of force: displacement, velocity or acceleration.
enum class FrfQuantity { Receptance, Mobility, Accelerance };
enum class FrfDirection { X, Y, Z };

struct FrfDataset {
  int index = 0;  // 1-based position of the dataset in its file, skipped datasets included
  FrfDirection response_direction = FrfDirection::X;
  FrfDirection reference_direction = FrfDirection::X;
  int response_node = 0;
  int reference_node = 0;
  FrfQuantity quantity = FrfQuantity::Receptance;
  std::vector<double> frequency_hz;          // strictly increasing
  std::vector<std::complex<double>> values;  // SI of `quantity`, one per frequency
  std::string name;                          // UFF record 1 (ID line 1), trimmed; empty for CSV
};

struct FrfFile {
  FrfFormat format = FrfFormat::Uff58;
  std::vector<FrfDataset> datasets;
  int skipped_datasets = 0;   // UFF datasets other than 58/58b (e.g. 15, 151, 164)
  int skipped_functions = 0;  // 58/58b datasets that are not translational FRFs (function type != 4 etc.)
};

// "receptance", "mobility", "accelerance"; "x", "y", "z".
std::string_view frfQuantityName(FrfQuantity q);
std::string_view frfDirectionName(FrfDirection d);

}  // namespace mx
