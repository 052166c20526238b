// FRF files by path: format detection from the content, reading and writing each format through
// QTemporaryDir, the CSV quantity the caller must give, and unreadable or unknown files.

#include "core/invalid_input.h"
#include "frf/frf_csv.h"
#include "frf/frf_file.h"
#include "frf/uff_writer.h"
#include "support/frf_samples.h"
#include "test_registry.h"

using namespace mx;

Q_DECLARE_METATYPE(mx::FrfFormat)

class TestFrfFile : public QObject {
  Q_OBJECT
 private slots:
  void detect_data() {
    QTest::addColumn<QString>("start");
    QTest::addColumn<int>("format");  // -1: none
    QTest::newRow("58") << "    -1\n    58\n" << static_cast<int>(FrfFormat::Uff58);
    QTest::newRow("58b") << "\n    -1\r\n    58b     1     2" << static_cast<int>(FrfFormat::Uff58b);
    QTest::newRow("151 first") << "    -1\n   151\n" << static_cast<int>(FrfFormat::Uff58);
    QTest::newRow("csv") << "frequency_Hz,real,imag\n" << static_cast<int>(FrfFormat::Csv);
    QTest::newRow("csv with BOM") << "\xef\xbb\xbf"
                                     "frequency_Hz,magnitude,phase_deg\n"
                                  << static_cast<int>(FrfFormat::Csv);
    QTest::newRow("other CSV") << "freq,real,imag\n" << static_cast<int>(FrfFormat::Csv);
    QTest::newRow("other text") << "hello\n" << -1;
    QTest::newRow("empty") << "" << -1;
  }
  void detect() {
    QFETCH(QString, start);
    QFETCH(int, format);
    const auto got = detectFrfFormat(start.toStdString());
    QCOMPARE(got ? static_cast<int>(*got) : -1, format);
  }

  void writeAndReadEachFormat_data() {
    QTest::addColumn<FrfFormat>("format");
    QTest::newRow("58") << FrfFormat::Uff58;
    QTest::newRow("58b") << FrfFormat::Uff58b;
    QTest::newRow("csv") << FrfFormat::Csv;
  }
  void writeAndReadEachFormat() {
    QFETCH(FrfFormat, format);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath("frf.dat").toStdString();
    const auto want = test::modalFrf(test::kTwoModes, FrfQuantity::Mobility, test::evenFrequencies(10.0, 2.5, 200));
    writeFrfFile(path, format, {want});
    const auto f = readFrfFile(path, FrfQuantity::Mobility);
    QCOMPARE(f.format, format);
    QCOMPARE(f.datasets.size(), std::size_t(1));
    const auto& got = f.datasets[0];
    QCOMPARE(got.quantity, FrfQuantity::Mobility);
    QCOMPARE(got.frequency_hz.size(), want.frequency_hz.size());
    for (std::size_t i = 0; i < want.values.size(); ++i)
      QCOMPARE_LE(std::abs(got.values[i] - want.values[i]), 1e-12 * std::abs(want.values[i]));
  }

  void csvNeedsTheQuantity() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("frf.csv").toStdString();
    test::writeBytes(path, "frequency_Hz,real,imag\n1,2,3\n");
    try {
      readFrfFile(path, std::nullopt);
      QFAIL("a CSV without a quantity was read");
    } catch (const FrfFileError& e) {
      QCOMPARE(std::string(e.what()), path +
                                          ": line 1: the CSV does not say its quantity: the caller must give "
                                          "receptance, mobility or accelerance");
    }
    QCOMPARE(readFrfFile(path, FrfQuantity::Accelerance).datasets.at(0).quantity, FrfQuantity::Accelerance);
  }

  // A universal file needs no quantity: records 9 and 10 say it.
  void uffIgnoresTheCsvQuantity() {
    const auto d = test::modalFrf(test::kTwoModes, FrfQuantity::Accelerance, {5.0, 6.0});
    const auto f = readFrf(uff58String({d}), "a.unv", std::nullopt);
    QCOMPARE(f.datasets.at(0).quantity, FrfQuantity::Accelerance);
  }

  void unknownCsvHeaderNamed() {
    try {
      readFrf("freq,re,im\n1,2,3\n", "a.csv", FrfQuantity::Receptance);
      QFAIL("an unknown CSV header was read");
    } catch (const FrfFileError& e) {
      QVERIFY2(
          std::string(e.what()).starts_with("a.csv: line 1: unknown CSV header: expected 'frequency_Hz,real,imag'"),
          e.what());
    }
  }

  void unknownContent() {
    try {
      readFrf("time value\n", "a.txt", FrfQuantity::Receptance);
      QFAIL("unknown content was read");
    } catch (const FrfFileError& e) {
      QCOMPARE(std::string(e.what()), std::string("a.txt: line 1: expected a universal file (a '    -1' line) or an "
                                                  "FRF CSV (a 'frequency_Hz,...' header)"));
    }
  }

  void unreadableAndUnwritable() {
    QTemporaryDir dir;
    const std::string missing = dir.filePath("none.unv").toStdString();
    try {
      readFrfFile(missing, std::nullopt);
      QFAIL("a missing file was read");
    } catch (const FrfFileError& e) {
      QCOMPARE(std::string(e.what()), missing + ": cannot be read (expected a readable file)");
    }
    const std::string bad = dir.filePath("no/such/dir/x.unv").toStdString();
    QVERIFY_THROWS_EXCEPTION(FrfFileError, writeFrfFile(bad, FrfFormat::Uff58, {}));
  }

  void csvTakesOneDataset() {
    QTemporaryDir dir;
    const auto d = test::modalFrf(test::kTwoModes, FrfQuantity::Receptance, {5.0, 6.0});
    QVERIFY_THROWS_EXCEPTION(InvalidInput, writeFrfFile(dir.filePath("a.csv").toStdString(), FrfFormat::Csv, {d, d}));
  }
};

MX_REGISTER_TEST(TestFrfFile)
#include "test_frf_file.moc"
