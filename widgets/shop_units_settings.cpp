#include "shop_units_settings.h"

#include <QSettings>

namespace mx::widgets {

namespace {
QString settingsKey(Quantity q) {
  return QStringLiteral("units/") + ShopUnits::quantityKey(q);
}
}  // namespace

ShopUnits readShopUnits(const QSettings& settings) {
  ShopUnits units;
  for (int i = 0; i < kQuantityCount; ++i) {
    const auto q = static_cast<Quantity>(i);
    units.setChoice(q, settings.value(settingsKey(q)).toString());  // unknown: stays the base unit
  }
  return units;
}

void writeShopUnits(QSettings& settings, const ShopUnits& units) {
  for (int i = 0; i < kQuantityCount; ++i) {
    const auto q = static_cast<Quantity>(i);
    settings.setValue(settingsKey(q), QString::fromLatin1(units.unit(q).key));
  }
}

}  // namespace mx::widgets
