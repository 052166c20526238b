// Fortran-formatted numbers: E and D exponents, touching fixed fields, and what is not a number.
#include "frf/fortran_number.h"
#include "test_registry.h"

using namespace mx;

class TestFortranNumber : public QObject {
  Q_OBJECT
 private slots:
  void numbers_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<double>("value");
    QTest::newRow("E13.5") << " -1.23456E+00" << -1.23456;
    QTest::newRow("E20.12") << "  9.765625000000E-01" << 0.9765625;
    QTest::newRow("D exponent") << "1.0D+03" << 1000.0;
    QTest::newRow("lower d") << "2.5d-1" << 0.25;
    QTest::newRow("plus sign") << "+2." << 2.0;
    QTest::newRow("leading point") << "-.5" << -0.5;
    QTest::newRow("integer") << "42" << 42.0;
    QTest::newRow("three-digit exponent") << "-1.000000000000E-300" << -1e-300;
    QTest::newRow("blanks around") << "\t 7.0 " << 7.0;
  }
  void numbers() {
    QFETCH(QString, text);
    QFETCH(double, value);
    double v = 0.0;
    QVERIFY(parseFortranNumber(text.toStdString(), v));
    QCOMPARE(v, value);
  }

  void notNumbers_data() {
    QTest::addColumn<QString>("text");
    QTest::newRow("word") << "abc";
    QTest::newRow("two points") << "1.2.3";
    QTest::newRow("exponent without digits") << "1E";
    QTest::newRow("exponent only") << "E5";
    QTest::newRow("two signs") << "--1";
    QTest::newRow("sign only") << "-";
    QTest::newRow("overflow") << "1.0E+999";
    QTest::newRow("nan") << "nan";
    QTest::newRow("trailing letter") << "1.0x";
    QTest::newRow("two numbers") << "1.0 2.0";
    QTest::newRow("empty") << "";
  }
  void notNumbers() {
    QFETCH(QString, text);
    double v = -7.0;
    QVERIFY(!parseFortranNumber(text.toStdString(), v));
    QCOMPARE(v, -7.0);  // untouched
  }

  // Negative fixed-width fields touch: each sign starts the next number.
  void touchingFields() {
    const std::string_view line = "-1.23456E+00-2.34567E-01 3.5D+00+4.0";
    std::vector<double> got;
    for (std::size_t p = skipBlanks(line, 0); p < line.size(); p = skipBlanks(line, p)) {
      double v = 0.0;
      QVERIFY(scanFortranNumber(line, p, v));
      got.push_back(v);
    }
    QCOMPARE(got, (std::vector<double>{-1.23456, -0.234567, 3.5, 4.0}));
  }

  void failedScanKeepsPosition() {
    std::size_t p = 4;
    double v = 0.0;
    QVERIFY(!scanFortranNumber("1.0 x2.0", p, v));
    QCOMPARE(p, std::size_t(4));
    QCOMPARE(tokenAt("1.0 x2.0 3", p), std::string_view("x2.0"));
    QCOMPARE(skipBlanks(" \t a", 0), std::size_t(3));
    QCOMPARE(skipBlanks("  ", 0), std::size_t(2));
  }
};

MX_REGISTER_TEST(TestFortranNumber)
#include "test_fortran_number.moc"
