// The Preferences dialog's shop-units page: one combo box per quantity with every unit and its exact
// factor, the "Metric" and "Inch" presets, and shopUnits() reading back what the combos show.
#include <QComboBox>
#include <QPushButton>

#include "shop_units_dialog.h"
#include "test_registry.h"

using mx::widgets::Quantity;
using mx::widgets::ShopUnits;
using mx::widgets::ShopUnitsDialog;

class TestShopUnitsDialog : public QObject {
  Q_OBJECT
 private slots:
  void combosNameEveryUnitWithItsFactor() {
    ShopUnitsDialog dialog;
    QCOMPARE(dialog.objectName(), QString("preferencesDialog"));
    QCOMPARE(dialog.combo(Quantity::Power)->objectName(), QString("units_power"));
    QCOMPARE(dialog.combo(Quantity::Power)->count(), 3);
    QCOMPARE(dialog.combo(Quantity::Power)->itemText(2), QString("hp (1 hp = 745.699872 W)"));
    QCOMPARE(dialog.combo(Quantity::Force)->itemText(1), QString("lbf (1 lbf = 4.4482216152605 N)"));
    QCOMPARE(dialog.combo(Quantity::SurfaceSpeed)->itemText(1), QString("SFM (1 SFM = 0.3048 m/min)"));
    QCOMPARE(dialog.combo(Quantity::Feed)->itemText(1), QString("IPM (1 IPM = 25.4 mm/min)"));
    QCOMPARE(dialog.combo(Quantity::RemovalRate)->itemText(1),
             QString::fromUtf8("in³/min (1 in³/min = 16.387064 cm³/min)"));
    QCOMPARE(dialog.combo(Quantity::Length)->itemText(0), QString("mm"));
  }

  void presets() {
    ShopUnitsDialog dialog;
    QCOMPARE(dialog.shopUnits(), ShopUnits::metric());
    dialog.inchButton()->click();
    QCOMPARE(dialog.shopUnits(), ShopUnits::inch());
    for (int q = 0; q < mx::widgets::kQuantityCount; ++q)
      QVERIFY(dialog.combo(Quantity(q))->currentText().startsWith(ShopUnits::inch().symbol(Quantity(q))));
    dialog.metricButton()->click();
    QCOMPARE(dialog.shopUnits(), ShopUnits::metric());
  }

  void eachQuantityOnItsOwn() {
    ShopUnitsDialog dialog;
    dialog.inchButton()->click();
    dialog.combo(Quantity::Power)->setCurrentIndex(1);  // kW with the rest in inch
    ShopUnits wanted = ShopUnits::inch();
    wanted.setChoice(Quantity::Power, "kW");
    QCOMPARE(dialog.shopUnits(), wanted);
    dialog.setShopUnits(ShopUnits::metric());
    QCOMPARE(dialog.combo(Quantity::Power)->currentIndex(), 0);
    dialog.setShopUnits(wanted);
    QCOMPARE(dialog.shopUnits(), wanted);
  }
};

MX_REGISTER_TEST(TestShopUnitsDialog)
#include "test_shop_units_dialog.moc"
