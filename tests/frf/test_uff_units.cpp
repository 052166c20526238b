// Units labels of dataset 58 records 8-10 to SI factors.
#include "frf/uff_units.h"
#include "support/frf_quantity_metatype.h"
#include "test_registry.h"

using namespace mx;

class TestUffUnits : public QObject {
  Q_OBJECT
 private slots:
  void numerator_data() {
    QTest::addColumn<FrfQuantity>("quantity");
    QTest::addColumn<QString>("label");
    QTest::addColumn<double>("factor");  // 0: not recognised
    const auto R = FrfQuantity::Receptance, V = FrfQuantity::Mobility, A = FrfQuantity::Accelerance;
    QTest::newRow("m") << R << "m" << 1.0;
    QTest::newRow("mm") << R << "MM" << 1e-3;
    QTest::newRow("um") << R << "um" << 1e-6;
    QTest::newRow("micro sign") << R << QString::fromUtf8("\xc2\xb5m") << 1e-6;
    QTest::newRow("in") << R << "in" << 0.0254;
    QTest::newRow("blank") << R << "" << 1.0;
    QTest::newRow("NONE") << V << "NONE" << 1.0;
    QTest::newRow("m/s") << V << "m/s" << 1.0;
    QTest::newRow("in/sec") << V << "in/sec" << 0.0254;
    QTest::newRow("mm/s") << V << "mm / s" << 1e-3;
    QTest::newRow("m/s^2") << A << "m/s^2" << 1.0;
    QTest::newRow("m/s**2") << A << "m/s**2" << 1.0;
    QTest::newRow("m/s2") << A << "m/s2" << 1.0;
    QTest::newRow("superscript two") << A << QString::fromUtf8("mm/s\xc2\xb2") << 1e-3;
    QTest::newRow("g") << A << "g" << 9.80665;
    QTest::newRow("G") << A << "G" << 9.80665;
    QTest::newRow("g's") << A << "g's" << 9.80665;
    QTest::newRow("m/s for receptance") << R << "m/s" << 0.0;
    QTest::newRow("m for mobility") << V << "m" << 0.0;
    QTest::newRow("ft") << R << "ft" << 0.0;
    QTest::newRow("V") << A << "V" << 0.0;
  }
  void numerator() {
    QFETCH(FrfQuantity, quantity);
    QFETCH(QString, label);
    QFETCH(double, factor);
    const auto f = numeratorUnitsToSi(quantity, label.toStdString());
    QCOMPARE(f.value_or(0.0), factor);
  }

  void force_data() {
    QTest::addColumn<QString>("label");
    QTest::addColumn<double>("factor");
    QTest::newRow("N") << "N" << 1.0;
    QTest::newRow("blank") << "" << 1.0;
    QTest::newRow("kN") << "kN" << 1e3;
    QTest::newRow("lbf") << "lbf" << 4.4482216152605;
    QTest::newRow("LB") << "LB" << 4.4482216152605;
    QTest::newRow("kg") << "kg" << 0.0;
    QTest::newRow("mN") << "mN" << 0.0;
  }
  void force() {
    QFETCH(QString, label);
    QFETCH(double, factor);
    QCOMPARE(forceUnitsToSi(label.toStdString()).value_or(0.0), factor);
  }

  void frequency() {
    QCOMPARE(frequencyUnitsToHz("Hz").value_or(0.0), 1.0);
    QCOMPARE(frequencyUnitsToHz("HZ").value_or(0.0), 1.0);
    QCOMPARE(frequencyUnitsToHz("").value_or(0.0), 1.0);
    QVERIFY(!frequencyUnitsToHz("rad/s"));
    QCOMPARE(normaliseUnitsLabel(" M / SEC**2 "), std::string("m/s^2"));
  }

  void time() {
    QCOMPARE(timeUnitsToSeconds("s").value_or(0.0), 1.0);
    QCOMPARE(timeUnitsToSeconds("Sec").value_or(0.0), 1.0);
    QCOMPARE(timeUnitsToSeconds("NONE").value_or(0.0), 1.0);
    QCOMPARE(timeUnitsToSeconds("ms").value_or(0.0), 1e-3);
    QCOMPARE(timeUnitsToSeconds("msec").value_or(0.0), 1e-3);
    QVERIFY(!timeUnitsToSeconds("Hz"));
    QVERIFY(!timeUnitsToSeconds("min"));
  }
};

MX_REGISTER_TEST(TestUffUnits)
#include "test_uff_units.moc"
