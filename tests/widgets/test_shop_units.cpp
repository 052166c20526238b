// Shop units: every display unit's exact factor to its base unit (1 in = 25.4 mm, 1 ft = 0.3048 m,
// 1 hp = 745.699872 W, 1 lbf = 4.4482216152605 N, 1 in³ = 16.387064 cm³), the round trip
// value -> display -> value, the presets, the readable number of digits, the text form of --units,
// and DisplayUnits: its length accessors (mm/inch as before) and one changed() per real change.
#include <QSignalSpy>
#include <cmath>

#include "display_units.h"
#include "shop_units.h"
#include "test_registry.h"

using mx::widgets::DisplayUnits;
using mx::widgets::Quantity;
using mx::widgets::ShopUnits;

Q_DECLARE_METATYPE(mx::widgets::Quantity)

class TestShopUnits : public QObject {
  Q_OBJECT
 private slots:
  // One row per display unit: base value, shown value, symbol.
  void conversions_data() {
    QTest::addColumn<Quantity>("quantity");
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("base");
    QTest::addColumn<double>("shown");
    QTest::addColumn<QString>("symbol");
    QTest::newRow("25.4 mm = 1 in") << Quantity::Length << "in" << 25.4 << 1.0 << "in";
    QTest::newRow("30 mm in mm") << Quantity::Length << "mm" << 30.0 << 30.0 << "mm";
    QTest::newRow("0.3048 m/min = 1 SFM") << Quantity::SurfaceSpeed << "ft/min" << 0.3048 << 1.0 << "SFM";
    QTest::newRow("304.8 m/min = 1000 SFM") << Quantity::SurfaceSpeed << "ft/min" << 304.8 << 1000.0 << "SFM";
    QTest::newRow("25.4 mm/min = 1 IPM") << Quantity::Feed << "in/min" << 25.4 << 1.0 << "IPM";
    QTest::newRow("1270 mm/min = 50 IPM") << Quantity::Feed << "in/min" << 1270.0 << 50.0 << "IPM";
    QTest::newRow("0.254 mm/tooth = 0.01 in/tooth") << Quantity::ChipLoad << "in/tooth" << 0.254 << 0.01 << "in/tooth";
    QTest::newRow("1500 W = 1.5 kW") << Quantity::Power << "kW" << 1500.0 << 1.5 << "kW";
    QTest::newRow("745.699872 W = 1 hp") << Quantity::Power << "hp" << 745.699872 << 1.0 << "hp";
    QTest::newRow("7456.99872 W = 10 hp") << Quantity::Power << "hp" << 7456.99872 << 10.0 << "hp";
    QTest::newRow("4.4482216152605 N = 1 lbf") << Quantity::Force << "lbf" << 4.4482216152605 << 1.0 << "lbf";
    QTest::newRow("444.82216152605 N = 100 lbf") << Quantity::Force << "lbf" << 444.82216152605 << 100.0 << "lbf";
    QTest::newRow("16.387064 cm3/min = 1 in3/min")
        << Quantity::RemovalRate << "in3/min" << 16.387064 << 1.0 << QString::fromUtf8("in³/min");
    QTest::newRow("cm3/min as is") << Quantity::RemovalRate << "cm3/min" << 12.5 << 12.5
                                   << QString::fromUtf8("cm³/min");
  }
  void conversions() {
    QFETCH(Quantity, quantity);
    QFETCH(QString, key);
    QFETCH(double, base);
    QFETCH(double, shown);
    QFETCH(QString, symbol);
    ShopUnits units;
    QVERIFY(units.setChoice(quantity, key));
    QCOMPARE(units.fromBase(quantity, base), shown);
    QCOMPARE(units.toBase(quantity, shown), base);
    QCOMPARE(units.symbol(quantity), symbol);
  }

  // value -> display -> value returns the value within one rounding of a double, for every unit.
  void roundTrip_data() {
    QTest::addColumn<double>("value");
    for (double v : {0.0, 1e-6, 0.1, 1.0, 25.4, 745.699872, 1234.5678, 1e7})
      QTest::newRow(qPrintable(QString::number(v, 'g', 10))) << v;
  }
  void roundTrip() {
    QFETCH(double, value);
    for (int q = 0; q < mx::widgets::kQuantityCount; ++q) {
      const auto quantity = static_cast<Quantity>(q);
      for (int c = 0; c < int(ShopUnits::choices(quantity).size()); ++c) {
        ShopUnits units;
        units.setChoice(quantity, c);
        const double back = units.toBase(quantity, units.fromBase(quantity, value));
        QVERIFY2(std::abs(back - value) <= 1e-15 * std::abs(value),
                 qPrintable(QString("%1 %2: %3 -> %4")
                                .arg(ShopUnits::quantityKey(quantity), units.unit(quantity).key)
                                .arg(value, 0, 'g', 17)
                                .arg(back, 0, 'g', 17)));
      }
    }
  }

  void presets() {
    const ShopUnits metric = ShopUnits::metric();
    const ShopUnits inch = ShopUnits::inch();
    QCOMPARE(metric, ShopUnits());
    const QStringList metric_symbols{"mm", "m/min", "mm/min", "mm/tooth", "W", "N", QString::fromUtf8("cm³/min")};
    const QStringList inch_symbols{"in", "SFM", "IPM", "in/tooth", "hp", "lbf", QString::fromUtf8("in³/min")};
    for (int q = 0; q < mx::widgets::kQuantityCount; ++q) {
      QCOMPARE(metric.symbol(Quantity(q)), metric_symbols[q]);
      QCOMPARE(inch.symbol(Quantity(q)), inch_symbols[q]);
      QCOMPARE(metric.unit(Quantity(q)).base_per_unit, 1.0);  // the project's own units
    }
  }

  void outOfRangeChoiceIsTheBaseUnit() {
    ShopUnits units = ShopUnits::inch();
    units.setChoice(Quantity::Power, 7);
    QCOMPARE(units.symbol(Quantity::Power), QString("W"));
    units.setChoice(Quantity::Force, -1);
    QCOMPARE(units.symbol(Quantity::Force), QString("N"));
    QVERIFY(!units.setChoice(Quantity::Force, "kN"));
    QCOMPARE(units.symbol(Quantity::Force), QString("N"));
  }

  // Enough digits to be read: the unit's decimals, at least three significant digits.
  void readableNumbers_data() {
    QTest::addColumn<Quantity>("quantity");
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("base");
    QTest::addColumn<QString>("text");
    QTest::newRow("MRR 0.02 cm3/min in in3/min") << Quantity::RemovalRate << "in3/min" << 0.02 << "0.00122";
    QTest::newRow("MRR 180 cm3/min") << Quantity::RemovalRate << "cm3/min" << 180.0 << "180.00";
    QTest::newRow("MRR 180 cm3/min in in3/min") << Quantity::RemovalRate << "in3/min" << 180.0 << "10.984";
    QTest::newRow("2745.3 W in hp") << Quantity::Power << "hp" << 2745.3 << "3.682";
    QTest::newRow("2745.3 W in kW") << Quantity::Power << "kW" << 2745.3 << "2.745";
    QTest::newRow("812.3 N in lbf") << Quantity::Force << "lbf" << 812.3 << "182.6";
    QTest::newRow("0.1 mm/tooth in in/tooth") << Quantity::ChipLoad << "in/tooth" << 0.1 << "0.00394";
    QTest::newRow("376.99 m/min in SFM") << Quantity::SurfaceSpeed << "ft/min" << 376.99 << "1237";
    QTest::newRow("zero") << Quantity::Force << "N" << 0.0 << "0.0";
    QTest::newRow("not finite") << Quantity::Force << "N" << std::nan("") << "\u2013";
  }
  void readableNumbers() {
    QFETCH(Quantity, quantity);
    QFETCH(QString, key);
    QFETCH(double, base);
    QFETCH(QString, text);
    ShopUnits units;
    QVERIFY(units.setChoice(quantity, key));
    QCOMPARE(units.number(quantity, base), text);
    if (std::isfinite(base)) QCOMPARE(units.format(quantity, base), text + " " + units.symbol(quantity));
  }

  void textForm_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("valid");
    QTest::addColumn<QString>("power");  // the symbol read, or the start of the reason
    QTest::newRow("metric") << "metric" << true << "W";
    QTest::newRow("inch") << "inch" << true << "hp";
    QTest::newRow("inch, kW") << "inch,power=kW" << true << "kW";
    QTest::newRow("items only") << "power=hp, force=lbf" << true << "hp";
    QTest::newRow("empty: metric") << "" << true << "W";
    QTest::newRow("unknown quantity") << "torque=Nm" << false << "units item 'torque=Nm': expected 'metric', 'inch'";
    QTest::newRow("unknown unit") << "power=PS" << false
                                  << "units item 'power=PS': unknown power unit 'PS' (allowed: W, kW, hp)";
    QTest::newRow("preset not first") << "power=kW,inch" << false << "units item 'inch'";
  }
  void textForm() {
    QFETCH(QString, text);
    QFETCH(bool, valid);
    QFETCH(QString, power);
    QString why;
    const std::optional<ShopUnits> units = ShopUnits::fromText(text, &why);
    QCOMPARE(units.has_value(), valid);
    if (valid)
      QCOMPARE(units->symbol(Quantity::Power), power);
    else
      QVERIFY2(why.startsWith(power), qPrintable(why));
  }

  void textRoundTrip() {
    ShopUnits units = ShopUnits::inch();
    units.setChoice(Quantity::Power, "kW");
    QCOMPARE(units.toText(),
             QString("length=in,surface_speed=ft/min,feed=in/min,chip_load=in/tooth,power=kW,force=lbf,mrr=in3/min"));
    QCOMPARE(ShopUnits::fromText(units.toText()), std::optional<ShopUnits>(units));
    QCOMPARE(ShopUnits::fromText(ShopUnits::metric().toText()), std::optional<ShopUnits>(ShopUnits::metric()));
  }

  // The mm/inch part keeps its old behaviour; one changed() per real change.
  void displayUnitsLengthAndSignal() {
    DisplayUnits units;
    QSignalSpy changed(&units, &DisplayUnits::changed);
    QCOMPARE(units.length(), DisplayUnits::Length::Millimetre);
    QCOMPARE(units.lengthSuffix(), QString("mm"));
    QCOMPARE(units.lengthDecimals(), 4);
    units.setLength(DisplayUnits::Length::Inch);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(units.fromMm(25.4), 1.0);
    QCOMPARE(units.toMm(0.5), 12.7);
    QCOMPARE(units.lengthSuffix(), QString("in"));
    QCOMPARE(units.lengthDecimals(), 5);
    QCOMPARE(units.shop().symbol(Quantity::Power), QString("W"));  // only the length changed
    units.setLength(DisplayUnits::Length::Inch);
    QCOMPARE(changed.count(), 1);
    units.setShop(ShopUnits::inch());
    QCOMPARE(changed.count(), 2);
    units.setShop(ShopUnits::inch());
    QCOMPARE(changed.count(), 2);
    QCOMPARE(&DisplayUnits::of(&units), &units.shop());
    QCOMPARE(DisplayUnits::of(nullptr), ShopUnits::metric());
  }
};

MX_REGISTER_TEST(TestShopUnits)
#include "test_shop_units.moc"
