// Universal file dataset 58 / 58b reader: records 6-10, the data layouts, units to SI, robustness to
// real-world text, skipped datasets, and one test per error case with its line or byte offset.
#include "frf/uff_reader.h"
#include "support/frf_samples.h"
#include "test_registry.h"

using namespace mx;
using mx::test::otherDataset;
using mx::test::rawBytes;
using mx::test::Uff58Text;

namespace {

Uff58Text twoPointComplex() {
  Uff58Text t;
  t.points = 2;
  t.x_min = 100.0;
  t.x_increment = 50.0;
  t.data = {"  1.000000000000E-06 -2.000000000000E-06  3.000000000000E-06 -4.000000000000E-06"};
  return t;
}

// The error's message and location for bytes that must not parse.
FrfFileError uffErrorOf(const std::string& bytes) {
  try {
    readUff(bytes, "tap.unv");
  } catch (const FrfFileError& e) {
    return e;
  }
  return FrfFileError("", -1, "no error");
}

}  // namespace

class TestUffReader : public QObject {
  Q_OBJECT
 private slots:
  void evenComplexDouble() {
    const auto f = readUff(twoPointComplex().text(), "tap.unv");
    QCOMPARE(f.format, FrfFormat::Uff58);
    QCOMPARE(f.datasets.size(), std::size_t(1));
    const auto& d = f.datasets[0];
    QCOMPARE(d.index, 1);
    QCOMPARE(d.name, std::string("tap x"));
    QCOMPARE(d.quantity, FrfQuantity::Receptance);
    QCOMPARE(d.frequency_hz, (std::vector<double>{100.0, 150.0}));
    QCOMPARE(d.values[0], std::complex<double>(1e-6, -2e-6));
    QCOMPARE(d.values[1], std::complex<double>(3e-6, -4e-6));
    QCOMPARE(f.skipped_datasets, 0);
    QCOMPARE(f.skipped_functions, 0);
  }

  // Each ordinate type in each spacing: the number of values per point and where the abscissa is.
  void ordinateTypesAndSpacing_data() {
    QTest::addColumn<int>("type");
    QTest::addColumn<int>("spacing");
    QTest::addColumn<QString>("data");
    QTest::addColumn<double>("f1");
    QTest::addColumn<double>("re1");
    QTest::addColumn<double>("im1");
    QTest::newRow("2 real single even") << 2 << 1 << " 1.00000E+00 2.00000E+00" << 11.0 << 2.0 << 0.0;
    QTest::newRow("4 real double even") << 4 << 1 << "  1.000000000000E+00  2.500000000000E+00" << 11.0 << 2.5 << 0.0;
    QTest::newRow("5 complex single even") << 5 << 1 << " 1.0E+00 2.0E+00 3.0E+00 4.0E+00" << 11.0 << 3.0 << 4.0;
    QTest::newRow("6 complex double even") << 6 << 1 << " 1.0 2.0\n 3.0 -4.0" << 11.0 << 3.0 << -4.0;
    QTest::newRow("2 real single uneven") << 2 << 0 << " 5.0 1.0 7.5 2.0" << 7.5 << 2.0 << 0.0;
    QTest::newRow("4 real double uneven") << 4 << 0 << " 5.0 1.0\n 7.5 2.0" << 7.5 << 2.0 << 0.0;
    QTest::newRow("5 complex single uneven") << 5 << 0 << " 5.0 1.0 2.0 7.5 3.0 4.0" << 7.5 << 3.0 << 4.0;
    QTest::newRow("6 complex double uneven") << 6 << 0 << " 5.0 1.0 2.0\n 7.5 3.0 4.0" << 7.5 << 3.0 << 4.0;
  }
  void ordinateTypesAndSpacing() {
    QFETCH(int, type);
    QFETCH(int, spacing);
    QFETCH(QString, data);
    QFETCH(double, f1);
    QFETCH(double, re1);
    QFETCH(double, im1);
    Uff58Text t;
    t.ordinate_type = type;
    t.spacing = spacing;
    t.x_min = 10.0;
    t.x_increment = 1.0;
    t.data = {data.toStdString()};
    const auto d = readUff(t.text(), "t.unv").datasets.at(0);
    QCOMPARE(d.frequency_hz.size(), std::size_t(2));
    QCOMPARE(d.frequency_hz[1], f1);
    QCOMPARE(d.values[1], std::complex<double>(re1, im1));
  }

  // The product of the direction signs multiplies the data; the axes come out positive.
  void directions_data() {
    QTest::addColumn<int>("response");
    QTest::addColumn<int>("reference");
    QTest::addColumn<int>("axis");
    QTest::addColumn<int>("reference_axis");
    QTest::addColumn<double>("sign");
    QTest::newRow("+x/+x") << 1 << 1 << 0 << 0 << 1.0;
    QTest::newRow("-x/+x") << -1 << 1 << 0 << 0 << -1.0;
    QTest::newRow("+x/-x") << 1 << -1 << 0 << 0 << -1.0;
    QTest::newRow("-y/-y") << -2 << -2 << 1 << 1 << 1.0;
    QTest::newRow("+z/-y") << 3 << -2 << 2 << 1 << -1.0;
  }
  void directions() {
    QFETCH(int, response);
    QFETCH(int, reference);
    QFETCH(int, axis);
    QFETCH(int, reference_axis);
    QFETCH(double, sign);
    auto t = twoPointComplex();
    t.response_dir = response;
    t.reference_dir = reference;
    t.response_node = 7;
    t.reference_node = 9;
    const auto d = readUff(t.text(), "t.unv").datasets.at(0);
    QCOMPARE(static_cast<int>(d.response_direction), axis);
    QCOMPARE(static_cast<int>(d.reference_direction), reference_axis);
    QCOMPARE(d.response_node, 7);
    QCOMPARE(d.reference_node, 9);
    QCOMPARE(d.values[0], sign * std::complex<double>(1e-6, -2e-6));
  }

  // Records 9 and 10 give the quantity and, with their units labels, the factor to SI.
  void quantitiesAndUnits_data() {
    QTest::addColumn<int>("numerator");
    QTest::addColumn<QString>("numerator_units");
    QTest::addColumn<QString>("force_units");
    QTest::addColumn<int>("quantity");
    QTest::addColumn<double>("factor");
    QTest::newRow("m/N") << 8 << "m"
                         << "N" << 0 << 1.0;
    QTest::newRow("mm/N") << 8 << "mm"
                          << "N" << 0 << 1e-3;
    QTest::newRow("in/lbf") << 8 << "in"
                            << "lbf" << 0 << 0.0254 / 4.4482216152605;
    QTest::newRow("mm/s / N") << 11 << "mm/s"
                              << "N" << 1 << 1e-3;
    QTest::newRow("m/s^2 / N") << 12 << "m/s^2"
                               << "N" << 2 << 1.0;
    QTest::newRow("g / N") << 12 << "g"
                           << "N" << 2 << 9.80665;
    QTest::newRow("g / lbf") << 12 << "G"
                             << "lbf" << 2 << 9.80665 / 4.4482216152605;
    QTest::newRow("blank labels are SI") << 12 << ""
                                         << "" << 2 << 1.0;
  }
  void quantitiesAndUnits() {
    QFETCH(int, numerator);
    QFETCH(QString, numerator_units);
    QFETCH(QString, force_units);
    QFETCH(int, quantity);
    QFETCH(double, factor);
    auto t = twoPointComplex();
    t.numerator_type = numerator;
    t.numerator_units = numerator_units.toStdString();
    t.denominator_units = force_units.toStdString();
    const auto d = readUff(t.text(), "t.unv").datasets.at(0);
    QCOMPARE(static_cast<int>(d.quantity), quantity);
    QCOMPARE_LE(std::abs(d.values[1] - factor * std::complex<double>(3e-6, -4e-6)), 1e-15 * factor);
  }

  // Fortran D exponents, fixed fields that touch, CRLF line ends, trailing blanks, no final newline.
  void realWorldText() {
    auto t = twoPointComplex();
    t.eol = "\r\n";
    t.name = "tap x   ";
    t.data = {"  1.0D-06-2.0D-06   ", "3.0d-06-4.00000E-06"};
    std::string text = t.text();
    text.resize(text.size() - 2);  // no final line end
    const auto d = readUff(text, "t.unv").datasets.at(0);
    QCOMPARE(d.name, std::string("tap x"));
    QCOMPARE(d.values[0], std::complex<double>(1e-6, -2e-6));
    QCOMPARE(d.values[1], std::complex<double>(3e-6, -4e-6));
  }

  void missingFinalDelimiterAccepted() {
    std::string text = twoPointComplex().text();
    text.resize(text.size() - std::string("    -1\n").size());
    QCOMPARE(readUff(text, "t.unv").datasets.at(0).values[1], std::complex<double>(3e-6, -4e-6));
  }

  // Several datasets: other types and other functions are skipped and counted; index counts all.
  void severalDatasetsAndSkips() {
    auto second = twoPointComplex();
    second.response_dir = 2;
    second.reference_dir = 2;
    auto not_frf = twoPointComplex();
    not_frf.function_type = 1;  // time response
    auto rotation = twoPointComplex();
    rotation.response_dir = 4;  // a rotation about x
    const std::string text = otherDataset(151) + otherDataset(164) + twoPointComplex().text() + otherDataset(15) +
                             not_frf.text() + rotation.text() + "\n" + second.text();
    const auto f = readUff(text, "t.unv");
    QCOMPARE(f.datasets.size(), std::size_t(2));
    QCOMPARE(f.skipped_datasets, 3);
    QCOMPARE(f.skipped_functions, 2);
    QCOMPARE(f.datasets[0].index, 3);
    QCOMPARE(f.datasets[1].index, 7);
    QCOMPARE(f.datasets[1].response_direction, FrfDirection::Y);
  }

  // Record 6 with blank entity names is read by its columns.
  void record6ByColumns() {
    auto t = twoPointComplex();
    std::string text = t.text();
    const std::string r6 =
        test::formatted("%5d%10d%5d%10d %-10s%10d%4d %-10s%10d%4d", 4, 1, 0, 0, "NONE", 12, -3, "NONE", 34, 3);
    const std::string blank =
        test::formatted("%5d%10d%5d%10d %-10s%10d%4d %-10s%10d%4d", 4, 1, 0, 0, "", 12, -3, "my ref", 34, 3);
    text.replace(text.find(r6.substr(0, 30)), 80, blank);
    const auto d = readUff(text, "t.unv");
    QCOMPARE(d.skipped_functions, 0);
    QCOMPARE(d.datasets.at(0).response_node, 12);
    QCOMPARE(d.datasets.at(0).reference_node, 34);
    QCOMPARE(d.datasets.at(0).response_direction, FrfDirection::Z);
    QCOMPARE(d.datasets.at(0).values[0], -std::complex<double>(1e-6, -2e-6));
  }

  void binaryLittleAndBigEndian_data() {
    QTest::addColumn<bool>("big");
    QTest::addColumn<bool>("single");
    QTest::newRow("little double") << false << false;
    QTest::newRow("big double") << true << false;
    QTest::newRow("little single") << false << true;
    QTest::newRow("big single") << true << true;
  }
  void binaryLittleAndBigEndian() {
    QFETCH(bool, big);
    QFETCH(bool, single);
    Uff58Text t;
    t.ordinate_type = single ? 5 : 6;
    t.spacing = 0;
    t.points = 2;
    const std::vector<double> v{10.0, 0.5, -0.25, 20.0, 1.5, 2.75};
    const std::string block = single ? rawBytes(std::vector<float>(v.begin(), v.end()), big) : rawBytes(v, big);
    const auto f = readUff(t.binaryText(block, big ? 2 : 1) + otherDataset(15), "t.unv");
    QCOMPARE(f.format, FrfFormat::Uff58b);
    QCOMPARE(f.skipped_datasets, 1);
    const auto& d = f.datasets.at(0);
    QCOMPARE(d.frequency_hz, (std::vector<double>{10.0, 20.0}));
    QCOMPARE(d.values[0], std::complex<double>(0.5, -0.25));
    QCOMPARE(d.values[1], std::complex<double>(1.5, 2.75));
  }

  // A block holding "\n" bytes: the lines after it are numbered as an editor shows them.
  void binaryBlockWithLineEndBytes() {
    Uff58Text t;
    t.ordinate_type = 4;
    t.points = 1;
    const std::string block = rawBytes(std::vector<double>{std::bit_cast<double>(0x3ff0'0a0a'0a0a'0a0aull)});
    const std::string text = t.binaryText(block) + "junk\n";
    const auto e = uffErrorOf(text);
    QCOMPARE(e.line(), 21);  // 2 + 11 header lines, 6 line-end bytes in the block, the "-1", then the junk
    QVERIFY(std::string(e.what()).find("expected '    -1' opening a dataset") != std::string::npos);
  }

  // Skipped 58b functions are jumped over by their byte count.
  void binaryOtherFunctionSkipped() {
    Uff58Text t;
    t.function_type = 2;
    const auto f = readUff(t.binaryText(std::string(32, '\n')) + twoPointComplex().text(), "t.unv");
    QCOMPARE(f.skipped_functions, 1);
    QCOMPARE(f.datasets.size(), std::size_t(1));
    QCOMPARE(f.datasets[0].index, 2);
  }

  // Each error case: the message names the file, where and what was expected.
  void errors_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("message");
    const std::string ok = twoPointComplex().text();
    auto t = twoPointComplex();
    std::string truncated = ok.substr(0, ok.find("    -1", 10));
    truncated.resize(truncated.size() - 20);
    QTest::newRow("truncated block") << QString::fromStdString(truncated) << 14
                                     << "tap.unv: line 14: truncated data: expected 4 values (2 points, record 7 at "
                                        "line 9), found 3 before the end of the file";
    QTest::newRow("truncated header") << QString::fromStdString(ok.substr(0, ok.find("NONE\n") + 5)) << 5
                                      << "tap.unv: line 5: expected record 3 of the dataset 58 at line 2";
    t.data = {" 1.0 2.0 x3.0 4.0"};
    QTest::newRow("non-number") << QString::fromStdString(t.text()) << 14
                                << "tap.unv: line 14: expected a number in record 12, found 'x3.0'";
    t.data = {" 1.0 2.0 3.0"};
    QTest::newRow("fewer points") << QString::fromStdString(t.text()) << 15
                                  << "tap.unv: line 15: point count does not match the header: expected 4 values";
    t.data = {" 1.0 2.0 3.0 4.0", " 5.0"};
    QTest::newRow("more points") << QString::fromStdString(t.text()) << 15
                                 << "tap.unv: line 15: point count does not match the header: more than the "
                                    "expected 4 values";
    t.spacing = 0;
    t.data = {" 10.0 1.0 2.0", " 10.0 3.0 4.0"};
    QTest::newRow("frequency repeated") << QString::fromStdString(t.text()) << 15
                                        << "tap.unv: line 15: expected increasing frequencies, found 10 after 10";
    t.data = {" 10.0 1.0 2.0", " 9.0 3.0 4.0"};
    QTest::newRow("frequency decreasing") << QString::fromStdString(t.text()) << 15
                                          << "tap.unv: line 15: expected increasing frequencies, found 9 after 10";
    auto even = twoPointComplex();
    even.x_increment = 0.0;
    QTest::newRow("zero increment") << QString::fromStdString(even.text()) << 9
                                    << "tap.unv: line 9: expected an abscissa increment > 0";
    auto force = twoPointComplex();
    force.denominator_type = 9;
    QTest::newRow("not force type") << QString::fromStdString(force.text()) << 12
                                    << "tap.unv: line 12: FRF not in force units: expected ordinate denominator type "
                                       "13 (force) (record 10), found 9";
    force.denominator_type = 13;
    force.denominator_units = "kg";
    QTest::newRow("not force units") << QString::fromStdString(force.text()) << 12
                                     << "tap.unv: line 12: FRF not in force units: expected N, kN or lbf (record 10), "
                                        "found 'kg'";
    auto numerator = twoPointComplex();
    numerator.numerator_type = 2;
    QTest::newRow("stress numerator") << QString::fromStdString(numerator.text()) << 11
                                      << "tap.unv: line 11: expected ordinate numerator type 8";
    numerator.numerator_type = 11;
    numerator.numerator_units = "furlong/s";
    QTest::newRow("unknown units") << QString::fromStdString(numerator.text()) << 11
                                   << "tap.unv: line 11: expected mobility numerator units (record 9, see "
                                      "uff_units.h), found 'furlong/s'";
    auto abscissa = twoPointComplex();
    abscissa.abscissa_units = "rpm";
    QTest::newRow("abscissa units") << QString::fromStdString(abscissa.text()) << 10
                                    << "tap.unv: line 10: expected abscissa units Hz (record 8), found 'rpm'";
    auto type = twoPointComplex();
    type.ordinate_type = 3;
    QTest::newRow("ordinate type") << QString::fromStdString(type.text()) << 9
                                   << "tap.unv: line 9: expected ordinate data type 2, 4, 5 or 6 (record 7), found 3";
    auto flat = twoPointComplex();
    flat.x_min = 1e20;
    flat.x_increment = 1.0;
    QTest::newRow("increment lost in rounding") << QString::fromStdString(flat.text()) << 9
                                                << "tap.unv: line 9: expected increasing finite frequencies: abscissa "
                                                   "minimum + increment x 1 does not increase (record 7)";
    auto overflow = twoPointComplex();
    overflow.numerator_units = "g";
    overflow.numerator_type = 12;
    overflow.data = {" 1.0 2.0 1.7E+308 1.0"};
    QTest::newRow("overflow in SI")
        << QString::fromStdString(overflow.text()) << 2
        << "tap.unv: line 2: expected values that are finite in SI units, point 2 overflows";
    auto huge = twoPointComplex();
    huge.points = 999999999;
    QTest::newRow("huge point count") << QString::fromStdString(huge.text()) << 15
                                      << "tap.unv: line 15: point count does not match the header: expected "
                                         "1999999998 values (999999999 points";
    QTest::newRow("junk before dataset") << "\n  hello\n"
                                         << 2
                                         << "tap.unv: line 2: expected '    -1' opening a dataset, found '  hello'";
    QTest::newRow("junk after dataset") << QString::fromStdString(ok + "garbage\n") << 16
                                        << "tap.unv: line 16: expected '    -1' opening a dataset, found 'garbage'";
  }
  void errors() {
    QFETCH(QString, text);
    QFETCH(int, line);
    QFETCH(QString, message);
    const auto e = uffErrorOf(text.toStdString());
    QCOMPARE(e.source(), std::string("tap.unv"));
    QCOMPARE(e.line(), line);
    QVERIFY(!e.blockOffset());
    QVERIFY2(QString(e.what()).startsWith(message), e.what());
  }

  void binaryErrors_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<int>("offset");
    QTest::addColumn<QString>("message");
    Uff58Text t;
    t.spacing = 0;
    const std::vector<double> v{10.0, 0.5, -0.25, 20.0, 1.5, 2.75};
    const std::string block = rawBytes(v);
    auto bytes = [](const std::string& s) { return QByteArray(s.data(), static_cast<qsizetype>(s.size())); };
    std::string cut = t.binaryText(block);
    cut.resize(cut.size() - 7 - 10);
    QTest::newRow("truncated") << bytes(cut) << 38
                               << "tap.unv: binary block of the dataset at line 2, byte 38: truncated binary block: "
                                  "expected 48 bytes";
    QTest::newRow("count") << bytes(t.binaryText(block.substr(0, 40))) << 0
                           << "tap.unv: binary block of the dataset at line 2, byte 0: point count does not match "
                              "the header: the block holds 40 bytes, expected 48";
    const std::vector<double> down{10.0, 0.5, -0.25, 5.0, 1.5, 2.75};
    QTest::newRow("frequency") << bytes(t.binaryText(rawBytes(down))) << 24
                               << "tap.unv: binary block of the dataset at line 2, byte 24: expected increasing "
                                  "frequencies";
    const std::vector<double> nan{10.0, std::nan(""), -0.25, 20.0, 1.5, 2.75};
    QTest::newRow("not finite") << bytes(t.binaryText(rawBytes(nan))) << 8
                                << "tap.unv: binary block of the dataset at line 2, byte 8: expected a finite value";
    auto skipped = t;
    skipped.function_type = 3;
    QTest::newRow("skipped, truncated") << bytes(skipped.binaryText(block, 1, 4000)) << 55
                                        << "tap.unv: binary block of the dataset at line 2, byte 55: truncated";
  }
  void binaryErrors() {
    QFETCH(QByteArray, text);
    QFETCH(int, offset);
    QFETCH(QString, message);
    const auto e = uffErrorOf(text.toStdString());
    QCOMPARE(e.line(), 2);
    QCOMPARE(e.blockOffset().value_or(9999), std::size_t(offset));
    QVERIFY2(QString(e.what()).startsWith(message), e.what());
  }

  void binaryIdentifierErrors_data() {
    QTest::addColumn<int>("order");
    QTest::addColumn<int>("float_format");
    QTest::addColumn<QString>("message");
    QTest::addColumn<QString>("bytes");
    QTest::newRow("byte order 3") << 3 << 2 << "tap.unv: line 2: expected byte ordering 1 (little endian) or 2"
                                  << "48";
    QTest::newRow("VAX floats") << 1 << 1 << "tap.unv: line 2: expected floating point format 2 (IEEE 754)"
                                << "48";
    QTest::newRow("absurd byte count") << 1 << 2
                                       << "tap.unv: line 2: expected the number of binary bytes (58b), found "
                                          "'1.0E+300'"
                                       << "1.0E+300";
  }
  void binaryIdentifierErrors() {
    QFETCH(int, order);
    QFETCH(int, float_format);
    QFETCH(QString, message);
    QFETCH(QString, bytes);
    const std::string text = "    -1\n" +
                             test::formatted("%6d%c%6d%6d%12d%12s%6d%6d%12d%12d", 58, 'b', order, float_format, 11,
                                             bytes.toStdString().c_str(), 0, 0, 0, 0) +
                             "\n";
    const auto e = uffErrorOf(text);
    QVERIFY2(QString(e.what()).startsWith(message), e.what());
  }

  void emptyInput() {
    const auto f = readUff("", "t.unv");
    QVERIFY(f.datasets.empty());
    QCOMPARE(f.skipped_datasets, 0);
  }
};

MX_REGISTER_TEST(TestUffReader)
#include "test_uff_reader.moc"
