// The shop units remembered per user: written to a QSettings file in a temporary folder (never the
// user's), read back by a new QSettings instance on the same file; missing or unknown values read as
// the base unit, and nothing else in the file changes.
#include <QSettings>
#include <QTemporaryDir>

#include "shop_units.h"
#include "shop_units_settings.h"
#include "test_registry.h"

using mx::widgets::Quantity;
using mx::widgets::ShopUnits;

class TestShopUnitsSettings : public QObject {
  Q_OBJECT
 private slots:
  void persistsAcrossANewInstance_data() {
    QTest::addColumn<QString>("units");
    QTest::newRow("metric") << "metric";
    QTest::newRow("inch") << "inch";
    QTest::newRow("mixed") << "metric,power=hp,mrr=in3/min,surface_speed=ft/min";
    QTest::newRow("kW and lbf") << "inch,power=kW,length=mm";
  }
  void persistsAcrossANewInstance() {
    QFETCH(QString, units);
    const std::optional<ShopUnits> wanted = ShopUnits::fromText(units);
    QVERIFY(wanted);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString file = dir.filePath("millexpert.ini");
    {
      QSettings settings(file, QSettings::IniFormat);
      settings.setValue("recentFiles", QStringList{"a.mxproj"});
      mx::widgets::writeShopUnits(settings, *wanted);
    }
    const QSettings fresh(file, QSettings::IniFormat);
    QCOMPARE(mx::widgets::readShopUnits(fresh), *wanted);
    QCOMPARE(fresh.value("recentFiles").toStringList(), QStringList{"a.mxproj"});
    QCOMPARE(fresh.value("units/power").toString(), QString::fromLatin1(wanted->unit(Quantity::Power).key));
  }

  void missingOrUnknownValuesAreTheBaseUnit() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString file = dir.filePath("millexpert.ini");
    QCOMPARE(mx::widgets::readShopUnits(QSettings(file, QSettings::IniFormat)), ShopUnits::metric());
    {
      QSettings settings(file, QSettings::IniFormat);
      settings.setValue("units/power", "PS");
      settings.setValue("units/force", "lbf");
      settings.setValue("units/length", 3);
    }
    const ShopUnits read = mx::widgets::readShopUnits(QSettings(file, QSettings::IniFormat));
    QCOMPARE(read.symbol(Quantity::Power), QString("W"));
    QCOMPARE(read.symbol(Quantity::Force), QString("lbf"));
    QCOMPARE(read.symbol(Quantity::Length), QString("mm"));
  }
};

MX_REGISTER_TEST(TestShopUnitsSettings)
#include "test_shop_units_settings.moc"
