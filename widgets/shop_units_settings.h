#pragma once
// The shop units remembered per user: one QSettings value per quantity, "units/<quantity key>" =
// "<unit key>" (e.g. "units/power" = "hp"). A missing or unknown value reads as the base unit.
#include "shop_units.h"

class QSettings;

namespace mx::widgets {

ShopUnits readShopUnits(const QSettings& settings);
void writeShopUnits(QSettings& settings, const ShopUnits& units);

}  // namespace mx::widgets
