#include "frf/uff_reader.h"

#include <cmath>
#include <vector>

#include "frf/uff58_scanner.h"
#include "frf/uff_units.h"

namespace mx {
namespace {

constexpr int kFrfFunctionType = 4;

struct Units {
  FrfQuantity quantity = FrfQuantity::Receptance;
  double frequency_factor = 1.0;
  double value_factor = 1.0;  // numerator to SI / denominator to SI, times the direction signs
};

std::string quoted(std::string_view s) {
  return "'" + std::string(s) + "'";
}

class FrfReader {
 public:
  FrfReader(std::string_view bytes, const std::string& source) : scanner_(bytes, source, "frequencies") {}

  FrfFile run() {
    FrfFile file;
    bool first_58 = true;
    Uff58Header h;
    while (scanner_.next(h)) {
      if (first_58) file.format = h.binary ? FrfFormat::Uff58b : FrfFormat::Uff58;
      first_58 = false;
      if (h.function_type != kFrfFunctionType || !isTranslationalUffDirection(h.response_dir) ||
          !isTranslationalUffDirection(h.reference_dir)) {
        ++file.skipped_functions;
        scanner_.skip(h);
        continue;
      }
      const Uff58Record7 r7 = scanner_.record7(h);
      Units u = readUnits(h);
      if ((h.response_dir < 0) != (h.reference_dir < 0)) u.value_factor = -u.value_factor;
      const std::vector<double> raw = scanner_.data(h, r7);
      file.datasets.push_back(makeDataset(h, r7, u, raw));
    }
    file.skipped_datasets = scanner_.skippedDatasets();
    return file;
  }

 private:
  FrfFileError error(int line, const std::string& expected) const { return scanner_.error(line, expected); }

  Units readUnits(const Uff58Header& h) const {
    const TextLine &r8 = h.records[8], &r9 = h.records[9], &r10 = h.records[10];
    Units u;
    const int abscissa = scanner_.specificDataType(h, 8);
    if (abscissa != 0 && abscissa != 18)
      throw error(r8.number,
                  "expected a frequency abscissa (record 8 type 18 or 0), found " + std::to_string(abscissa));
    const auto hz = frequencyUnitsToHz(uffUnitsLabel(r8.text));
    if (!hz) throw error(r8.number, "expected abscissa units Hz (record 8), found " + quoted(uffUnitsLabel(r8.text)));
    u.frequency_factor = *hz;

    switch (scanner_.specificDataType(h, 9)) {
      case 8:
        u.quantity = FrfQuantity::Receptance;
        break;
      case 11:
        u.quantity = FrfQuantity::Mobility;
        break;
      case 12:
        u.quantity = FrfQuantity::Accelerance;
        break;
      default:
        throw error(r9.number,
                    "expected ordinate numerator type 8 (displacement), 11 (velocity) or 12 (acceleration) (record 9)");
    }
    const auto num = numeratorUnitsToSi(u.quantity, uffUnitsLabel(r9.text));
    if (!num)
      throw error(r9.number, "expected " + std::string(frfQuantityName(u.quantity)) +
                                 " numerator units (record 9, see uff_units.h), found " +
                                 quoted(uffUnitsLabel(r9.text)));
    const int denominator = scanner_.specificDataType(h, 10);
    if (denominator != 13)
      throw error(r10.number,
                  "FRF not in force units: expected ordinate denominator type 13 (force) (record 10), found " +
                      std::to_string(denominator));
    const auto force = forceUnitsToSi(uffUnitsLabel(r10.text));
    if (!force)
      throw error(r10.number, "FRF not in force units: expected N, kN or lbf (record 10), found " +
                                  quoted(uffUnitsLabel(r10.text)));
    u.value_factor = *num / *force;
    return u;
  }

  static FrfDirection axis(int dir) { return static_cast<FrfDirection>(std::abs(dir) - 1); }

  // The dataset from record 12's values; an even abscissa must still increase once rounded (a large
  // minimum swallows a small increment) and the values must stay finite in SI units.
  FrfDataset makeDataset(const Uff58Header& h, const Uff58Record7& r7, const Units& u,
                         const std::vector<double>& raw) const {
    FrfDataset d;
    d.index = h.index;
    d.name = h.name;
    d.response_node = h.response_node;
    d.reference_node = h.reference_node;
    d.response_direction = axis(h.response_dir);
    d.reference_direction = axis(h.reference_dir);
    d.quantity = u.quantity;
    const auto n = static_cast<std::size_t>(r7.points);
    const std::size_t stride = r7.componentsPerPoint();
    const std::size_t first = r7.even ? 0 : 1;
    d.frequency_hz.resize(n);
    d.values.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double* v = raw.data() + i * stride;
      const double x = r7.even ? r7.x_min + static_cast<double>(i) * r7.x_increment : v[0];
      d.frequency_hz[i] = x * u.frequency_factor;
      if (!std::isfinite(d.frequency_hz[i]) || (i > 0 && !(d.frequency_hz[i] > d.frequency_hz[i - 1])))
        throw error(r7.line, "expected increasing finite frequencies: abscissa minimum + increment x " +
                                 std::to_string(i) + " does not increase (record 7)");
      const double im = r7.complex() ? v[first + 1] : 0.0;
      d.values[i] = std::complex<double>(v[first], im) * u.value_factor;
      if (!std::isfinite(d.values[i].real()) || !std::isfinite(d.values[i].imag()))
        throw error(h.id_line,
                    "expected values that are finite in SI units, point " + std::to_string(i + 1) + " overflows");
    }
    return d;
  }

  Uff58Scanner scanner_;
};

}  // namespace

FrfFile readUff(std::string_view bytes, const std::string& source_name) {
  return FrfReader(bytes, source_name).run();
}

}  // namespace mx
