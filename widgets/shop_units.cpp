#include "shop_units.h"

#include <QCoreApplication>
#include <QObject>
#include <algorithm>
#include <cmath>

namespace mx::widgets {

namespace {

// The first unit of each quantity is its base unit. Decimals: a field reads to about the resolution a
// shop writes (0.1 m/min, 1 SFM, 0.01 IPM, 0.0001 mm/tooth, 0.00001 in/tooth...).
constexpr UnitSpec kLength[] = {{"mm", "mm", 1.0, 4}, {"in", "in", 25.4, 5}};
constexpr UnitSpec kSurfaceSpeed[] = {{"m/min", "m/min", 1.0, 1}, {"ft/min", "SFM", 0.3048, 0}};
constexpr UnitSpec kFeed[] = {{"mm/min", "mm/min", 1.0, 1}, {"in/min", "IPM", 25.4, 2}};
constexpr UnitSpec kChipLoad[] = {{"mm/tooth", "mm/tooth", 1.0, 4}, {"in/tooth", "in/tooth", 25.4, 5}};
constexpr UnitSpec kPower[] = {{"W", "W", 1.0, 1}, {"kW", "kW", 1000.0, 3}, {"hp", "hp", 745.699872, 3}};
constexpr UnitSpec kForce[] = {{"N", "N", 1.0, 1}, {"lbf", "lbf", 4.4482216152605, 1}};
constexpr UnitSpec kRemovalRate[] = {{"cm3/min", "cm\u00b3/min", 1.0, 2}, {"in3/min", "in\u00b3/min", 16.387064, 3}};

struct QuantitySpec {
  Quantity quantity;
  const char* key;
  const char* name;
  std::span<const UnitSpec> units;
};

const QuantitySpec kQuantities[kQuantityCount] = {
    {Quantity::Length, "length", QT_TRANSLATE_NOOP("ShopUnits", "Length"), kLength},
    {Quantity::SurfaceSpeed, "surface_speed", QT_TRANSLATE_NOOP("ShopUnits", "Surface speed v_c"), kSurfaceSpeed},
    {Quantity::Feed, "feed", QT_TRANSLATE_NOOP("ShopUnits", "Feed rate v_f"), kFeed},
    {Quantity::ChipLoad, "chip_load", QT_TRANSLATE_NOOP("ShopUnits", "Chip load (feed per tooth) s_t"), kChipLoad},
    {Quantity::Power, "power", QT_TRANSLATE_NOOP("ShopUnits", "Power"), kPower},
    {Quantity::Force, "force", QT_TRANSLATE_NOOP("ShopUnits", "Force"), kForce},
    {Quantity::RemovalRate, "mrr", QT_TRANSLATE_NOOP("ShopUnits", "Material removal rate MRR"), kRemovalRate},
};

const QuantitySpec& spec(Quantity q) {
  return kQuantities[static_cast<std::size_t>(q)];
}

QString keysOf(Quantity q) {
  QStringList keys;
  for (const UnitSpec& u : ShopUnits::choices(q)) keys << QString::fromLatin1(u.key);
  return keys.join(", ");
}

}  // namespace

ShopUnits ShopUnits::metric() {
  return ShopUnits();
}

ShopUnits ShopUnits::inch() {
  ShopUnits u;
  u.choice_ = {1, 1, 1, 1, 2, 1, 1};  // in, SFM, IPM, in/tooth, hp, lbf, in³/min
  return u;
}

std::span<const UnitSpec> ShopUnits::choices(Quantity q) {
  return spec(q).units;
}

QString ShopUnits::quantityKey(Quantity q) {
  return QString::fromLatin1(spec(q).key);
}

QString ShopUnits::quantityName(Quantity q) {
  return QCoreApplication::translate("ShopUnits", spec(q).name);
}

std::optional<Quantity> ShopUnits::quantityFromKey(const QString& key) {
  for (const QuantitySpec& s : kQuantities)
    if (key == QLatin1String(s.key)) return s.quantity;
  return std::nullopt;
}

void ShopUnits::setChoice(Quantity q, int choice) {
  const int count = static_cast<int>(choices(q).size());
  choice_[index(q)] = choice >= 0 && choice < count ? choice : 0;
}

bool ShopUnits::setChoice(Quantity q, const QString& key) {
  const std::span<const UnitSpec> units = choices(q);
  for (std::size_t i = 0; i < units.size(); ++i) {
    if (key == QLatin1String(units[i].key)) {
      choice_[index(q)] = static_cast<int>(i);
      return true;
    }
  }
  return false;
}

int ShopUnits::readableDecimals(double shown, int decimals) {
  if (!std::isfinite(shown) || shown == 0.0) return decimals;
  const int leading = static_cast<int>(std::floor(std::log10(std::abs(shown))));
  return std::clamp(std::max(decimals, 2 - leading), 0, 9);
}

QString ShopUnits::number(Quantity q, double base) const {
  const double shown = fromBase(q, base);
  if (!std::isfinite(shown)) return QStringLiteral("\u2013");
  return QString::number(shown, 'f', readableDecimals(shown, decimals(q)));
}

QString ShopUnits::format(Quantity q, double base) const {
  return number(q, base) + QLatin1Char(' ') + symbol(q);
}

QString ShopUnits::toText() const {
  QStringList items;
  for (const QuantitySpec& s : kQuantities) items << QString("%1=%2").arg(s.key, unit(s.quantity).key);
  return items.join(',');
}

std::optional<ShopUnits> ShopUnits::fromText(const QString& text, QString* error) {
  const auto fail = [error](const QString& why) -> std::optional<ShopUnits> {
    if (error) *error = why;
    return std::nullopt;
  };
  ShopUnits units;
  const QStringList items = text.split(',', Qt::SkipEmptyParts);
  for (qsizetype i = 0; i < items.size(); ++i) {
    const QString item = items[i].trimmed();
    if (i == 0 && (item == QLatin1String("metric") || item == QLatin1String("inch"))) {
      units = item == QLatin1String("inch") ? inch() : metric();
      continue;
    }
    const qsizetype eq = item.indexOf('=');
    const std::optional<Quantity> q = quantityFromKey(eq < 0 ? item : item.left(eq).trimmed());
    if (eq < 0 || !q) {
      QStringList keys;
      for (const QuantitySpec& s : kQuantities) keys << QString::fromLatin1(s.key);
      return fail(QObject::tr("units item '%1': expected 'metric', 'inch' or QUANTITY=UNIT with QUANTITY one of %2")
                      .arg(item.left(80), keys.join(", ")));
    }
    const QString value = item.mid(eq + 1).trimmed();
    if (!units.setChoice(*q, value))
      return fail(QObject::tr("units item '%1': unknown %2 unit '%3' (allowed: %4)")
                      .arg(item.left(80), quantityKey(*q), value.left(40), keysOf(*q)));
  }
  return units;
}

}  // namespace mx::widgets
