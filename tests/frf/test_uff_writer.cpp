// Dataset 58 / 58b writers: the record layout, and the round trips (58b bit for bit, 58 to 12 digits).
#include <bit>
#include <cstdint>

#include "core/invalid_input.h"
#include "frf/uff_reader.h"
#include "frf/uff_writer.h"
#include "support/frf_quantity_metatype.h"
#include "support/frf_samples.h"
#include "test_registry.h"

using namespace mx;
using mx::test::evenFrequencies;
using mx::test::kTwoModes;
using mx::test::modalFrf;

namespace {

std::vector<FrfDataset> sample(FrfQuantity q) {
  auto x = modalFrf(kTwoModes, q, evenFrequencies(0.0, 0.9765625, 400), FrfDirection::X);
  auto z = modalFrf(kTwoModes, q, {1.0 / 3.0, 2.0 / 3.0, 1e5 + 1.0 / 7.0}, FrfDirection::Z);
  z.name = "z tap";
  z.index = 2;
  z.response_node = 5;
  z.reference_node = 6;
  z.values[1] = {-1e-300, 4.9e-324};  // three-digit exponent fields touch; a denormal
  return {x, z};
}

bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void compareMetadata(const FrfDataset& got, const FrfDataset& want) {
  QCOMPARE(got.name, want.name);
  QCOMPARE(got.quantity, want.quantity);
  QCOMPARE(got.response_direction, want.response_direction);
  QCOMPARE(got.reference_direction, want.reference_direction);
  QCOMPARE(got.response_node, want.response_node);
  QCOMPARE(got.reference_node, want.reference_node);
  QCOMPARE(got.frequency_hz.size(), want.frequency_hz.size());
}

}  // namespace

class TestUffWriter : public QObject {
  Q_OBJECT
 private slots:
  void quantities_data() {
    QTest::addColumn<FrfQuantity>("quantity");
    QTest::newRow("receptance") << FrfQuantity::Receptance;
    QTest::newRow("mobility") << FrfQuantity::Mobility;
    QTest::newRow("accelerance") << FrfQuantity::Accelerance;
  }

  void binaryRoundTripIsBitExact_data() { quantities_data(); }
  void binaryRoundTripIsBitExact() {
    QFETCH(FrfQuantity, quantity);
    const auto want = sample(quantity);
    const auto f = readUff(uff58bString(want), "w.uff");
    QCOMPARE(f.format, FrfFormat::Uff58b);
    QCOMPARE(f.datasets.size(), want.size());
    for (std::size_t k = 0; k < want.size(); ++k) {
      const auto& got = f.datasets[k];
      compareMetadata(got, want[k]);
      QCOMPARE(got.index, static_cast<int>(k) + 1);
      for (std::size_t i = 0; i < got.values.size(); ++i) {
        QVERIFY(sameBits(got.frequency_hz[i], want[k].frequency_hz[i]));
        QVERIFY(sameBits(got.values[i].real(), want[k].values[i].real()));
        QVERIFY(sameBits(got.values[i].imag(), want[k].values[i].imag()));
      }
    }
  }

  void asciiRoundTripTo12Digits_data() { quantities_data(); }
  void asciiRoundTripTo12Digits() {
    QFETCH(FrfQuantity, quantity);
    const auto want = sample(quantity);
    const auto f = readUff(uff58String(want), "w.unv");
    QCOMPARE(f.format, FrfFormat::Uff58);
    QCOMPARE(f.datasets.size(), want.size());
    auto close = [](double a, double b) { return std::abs(a - b) <= 5e-13 * std::abs(b); };
    for (std::size_t k = 0; k < want.size(); ++k) {
      const auto& got = f.datasets[k];
      compareMetadata(got, want[k]);
      for (std::size_t i = 0; i < got.values.size(); ++i) {
        QVERIFY(close(got.frequency_hz[i], want[k].frequency_hz[i]));
        QVERIFY2(close(got.values[i].real(), want[k].values[i].real()), std::to_string(i).c_str());
        QVERIFY(close(got.values[i].imag(), want[k].values[i].imag()));
      }
    }
  }

  // The records in their fixed formats: record 6 80 columns, record 12 three E20.12 fields a line.
  void asciiLayout() {
    auto d = modalFrf(kTwoModes, FrfQuantity::Accelerance, {100.0, 200.0}, FrfDirection::Y);
    d.name = "tap";
    const std::string text = uff58String({d});
    QStringList lines = QString::fromStdString(text).split('\n');
    QCOMPARE(lines.size(), 17);  // 2 + 11 + 2 data + "-1", then the empty rest after the last line end
    QCOMPARE(lines[0], QString("    -1"));
    QCOMPARE(lines[1], QString("    58"));
    QCOMPARE(lines[2], QString("tap"));
    QCOMPARE(lines[7], QString("    4         1    0         0 NONE               1   2 NONE               1   2"));
    QCOMPARE(lines[8].left(30), QString("         6         2         0"));
    QCOMPARE(lines[10].trimmed(), QString("12    1    0    0 Acceleration         m/s^2"));
    QCOMPARE(lines[11].trimmed(), QString("13    0    1    0 Force                N"));
    QCOMPARE(lines[13].size(), 60);
    QCOMPARE(lines[13].left(20), QString("  1.000000000000E+02"));
    QCOMPARE(lines[15], QString("    -1"));
  }

  void binaryIdentifier() {
    const auto d = modalFrf(kTwoModes, FrfQuantity::Receptance, {100.0, 200.0});
    const std::string text = uff58bString({d});
    QCOMPARE(text.substr(0, 7 + 79 + 1), std::string("    -1\n    58b     1     2          11          48     0     0"
                                                     "           0           0\n"));
    QCOMPARE(text.substr(text.size() - 7), std::string("    -1\n"));
  }

  void mismatchedLengthsRejected() {
    auto d = modalFrf(kTwoModes, FrfQuantity::Receptance, {100.0, 200.0});
    d.values.pop_back();
    QVERIFY_THROWS_EXCEPTION(InvalidInput, uff58String({d}));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, uff58bString({d}));
  }
};

MX_REGISTER_TEST(TestUffWriter)
#include "test_uff_writer.moc"
