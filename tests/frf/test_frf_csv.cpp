// FRF CSV: the two header forms, tolerated text, the errors with their lines, and the exact round trip.
#include <cstring>

#include "core/invalid_input.h"
#include "frf/frf_csv.h"
#include "support/frf_samples.h"
#include "test_registry.h"

using namespace mx;

namespace {

FrfFileError csvErrorOf(const std::string& bytes) {
  try {
    readFrfCsv(bytes, "tap.csv", FrfQuantity::Receptance);
  } catch (const FrfFileError& e) {
    return e;
  }
  return FrfFileError("", -1, "no error");
}

}  // namespace

class TestFrfCsv : public QObject {
  Q_OBJECT
 private slots:
  void cartesian() {
    const auto d =
        readFrfCsv("frequency_Hz,real,imag\n10,1e-6,-2e-6\n20.5, 3.0E-06 ,4D-6\n", "a.csv", FrfQuantity::Mobility);
    QCOMPARE(d.quantity, FrfQuantity::Mobility);
    QCOMPARE(d.index, 1);
    QCOMPARE(d.frequency_hz, (std::vector<double>{10.0, 20.5}));
    QCOMPARE(d.values[0], std::complex<double>(1e-6, -2e-6));
    QCOMPARE(d.values[1], std::complex<double>(3e-6, 4e-6));
  }

  void polar_data() {
    QTest::addColumn<double>("magnitude");
    QTest::addColumn<double>("phase");
    QTest::addColumn<double>("re");
    QTest::addColumn<double>("im");
    QTest::newRow("0 deg") << 2.0 << 0.0 << 2.0 << 0.0;
    QTest::newRow("90 deg") << 2.0 << 90.0 << 0.0 << 2.0;
    QTest::newRow("-90 deg") << 1e-6 << -90.0 << 0.0 << -1e-6;
    QTest::newRow("180 deg") << 3.0 << 180.0 << -3.0 << 0.0;
    QTest::newRow("-135 deg") << std::sqrt(2.0) << -135.0 << -1.0 << -1.0;
    QTest::newRow("zero magnitude") << 0.0 << 45.0 << 0.0 << 0.0;
  }
  void polar() {
    QFETCH(double, magnitude);
    QFETCH(double, phase);
    QFETCH(double, re);
    QFETCH(double, im);
    const std::string text =
        "frequency_Hz,magnitude,phase_deg\n" + test::formatted("5,%.17g,%.17g\n", magnitude, phase);
    const auto d = readFrfCsv(text, "a.csv", FrfQuantity::Receptance);
    QCOMPARE_LE(std::abs(d.values.at(0) - std::complex<double>(re, im)), 1e-15 * std::max(1.0, magnitude));
  }

  void toleratedText() {
    const auto d = readFrfCsv(
        "\xef\xbb\xbf"
        "frequency_Hz,real,imag  \r\n\r\n1,2,3\r\n2,4,5",
        "a.csv", FrfQuantity::Receptance);
    QCOMPARE(d.frequency_hz, (std::vector<double>{1.0, 2.0}));
    QCOMPARE(d.values[1], std::complex<double>(4.0, 5.0));
  }

  void errors_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown header") << "freq,real,imag\n1,2,3\n"
                                    << 1
                                    << "tap.csv: line 1: unknown CSV header: expected 'frequency_Hz,real,imag' or "
                                       "'frequency_Hz,magnitude,phase_deg', found 'freq,real,imag'";
    QTest::newRow("header case") << "frequency_hz,real,imag\n" << 1 << "tap.csv: line 1: unknown CSV header";
    QTest::newRow("two columns") << "frequency_Hz,real\n" << 1 << "tap.csv: line 1: unknown CSV header";
    QTest::newRow("empty") << "" << 1 << "tap.csv: line 1: expected the CSV header";
    QTest::newRow("non-number") << "frequency_Hz,real,imag\n1,2,3\n2,abc,3\n"
                                << 3 << "tap.csv: line 3: expected a number in column 2, found 'abc'";
    QTest::newRow("empty field") << "frequency_Hz,real,imag\n1,,3\n"
                                 << 2 << "tap.csv: line 2: expected a number in column 2, found ''";
    QTest::newRow("missing field") << "frequency_Hz,real,imag\n1,2\n"
                                   << 2 << "tap.csv: line 2: expected three comma-separated numbers, found '1,2'";
    QTest::newRow("extra field") << "frequency_Hz,real,imag\n1,2,3,4\n"
                                 << 2 << "tap.csv: line 2: expected three comma-separated numbers";
    QTest::newRow("frequency repeated") << "frequency_Hz,real,imag\n1,2,3\n1,2,3\n"
                                        << 3 << "tap.csv: line 3: expected increasing frequencies";
    QTest::newRow("frequency decreasing") << "frequency_Hz,real,imag\n2,2,3\n\n1,2,3\n"
                                          << 4 << "tap.csv: line 4: expected increasing frequencies";
    QTest::newRow("negative magnitude") << "frequency_Hz,magnitude,phase_deg\n1,-2,3\n"
                                        << 2 << "tap.csv: line 2: expected a magnitude >= 0";
  }
  void errors() {
    QFETCH(QString, text);
    QFETCH(int, line);
    QFETCH(QString, message);
    const auto e = csvErrorOf(text.toStdString());
    QCOMPARE(e.line(), line);
    QVERIFY2(QString(e.what()).startsWith(message), e.what());
  }

  void roundTripIsExact() {
    const auto want =
        test::modalFrf(test::kTwoModes, FrfQuantity::Accelerance, test::evenFrequencies(0.1, 1.0 / 3, 50));
    const std::string text = frfCsvString(want);
    QVERIFY(text.starts_with("frequency_Hz,real,imag\n"));
    const auto got = readFrfCsv(text, "a.csv", FrfQuantity::Accelerance);
    QCOMPARE(got.frequency_hz.size(), want.frequency_hz.size());
    for (std::size_t i = 0; i < want.values.size(); ++i) {
      QCOMPARE(got.frequency_hz[i], want.frequency_hz[i]);
      QCOMPARE(got.values[i], want.values[i]);
    }
  }

  void mismatchedLengthsRejected() {
    auto d = test::modalFrf(test::kTwoModes, FrfQuantity::Receptance, {1.0, 2.0});
    d.frequency_hz.pop_back();
    QVERIFY_THROWS_EXCEPTION(InvalidInput, frfCsvString(d));
  }
};

MX_REGISTER_TEST(TestFrfCsv)
#include "test_frf_csv.moc"
