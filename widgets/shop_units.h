#pragma once
// Shop units: the unit each view shows and accepts for lengths, surface speeds, feed rates, chip loads,
// power, forces and material removal rates. Only the display changes: the project file stays SI and
// shop-metric, and the engine SI. Every quantity has a base unit (its metric shop unit: mm, m/min,
// mm/min, mm/tooth, W, N, cm³/min) and a few display units, each an exact multiple of the base:
//   1 in = 25.4 mm, 1 ft = 0.3048 m (international yard and pound agreement, 1959),
//   1 hp = 745.699872 W (mechanical horsepower, 550 ft·lbf/s),
//   1 lbf = 4.4482216152605 N (1 lb = 0.45359237 kg times standard gravity 9.80665 m/s²),
//   1 in³ = 16.387064 cm³ (2.54³).
#include <QString>
#include <QStringList>
#include <array>
#include <optional>
#include <span>

namespace mx::widgets {

enum class Quantity { Length, SurfaceSpeed, Feed, ChipLoad, Power, Force, RemovalRate };
inline constexpr int kQuantityCount = 7;

struct UnitSpec {
  const char* key;       // settings and --units value: "mm", "in", "m/min", "ft/min", "hp", "in3/min"...
  const char* symbol;    // what labels show: "mm", "SFM", "IPM", "cm³/min"... (UTF-8)
  double base_per_unit;  // base units in one of this unit (exact)
  int decimals;          // fixed decimals of a field in this unit
};

class ShopUnits {
 public:
  static ShopUnits metric();  // mm, m/min, mm/min, mm/tooth, W, N, cm³/min (the default)
  static ShopUnits inch();    // in, SFM, IPM, in/tooth, hp, lbf, in³/min

  static std::span<const UnitSpec> choices(Quantity q);
  static QString quantityKey(Quantity q);   // "length", "surface_speed", "feed", "chip_load", "power", "force", "mrr"
  static QString quantityName(Quantity q);  // "Length", "Surface speed", ...
  static std::optional<Quantity> quantityFromKey(const QString& key);

  int choice(Quantity q) const { return choice_[index(q)]; }
  void setChoice(Quantity q, int choice);  // out of range: the base unit
  // Sets the unit whose key is `key`; false (nothing changes) when the quantity has no such unit.
  bool setChoice(Quantity q, const QString& key);
  const UnitSpec& unit(Quantity q) const { return choices(q)[std::size_t(choice(q))]; }
  QString symbol(Quantity q) const { return QString::fromUtf8(unit(q).symbol); }
  int decimals(Quantity q) const { return unit(q).decimals; }

  double fromBase(Quantity q, double base) const { return base / unit(q).base_per_unit; }
  double toBase(Quantity q, double shown) const { return shown * unit(q).base_per_unit; }

  // The shown number of a base value: the unit's decimals, more for small values so that at least
  // three significant digits show ("0.00122" in³/min, not "0.001"); "–" when not finite.
  QString number(Quantity q, double base) const;
  QString format(Quantity q, double base) const;  // number + " " + symbol
  static int readableDecimals(double shown, int decimals);

  // "length=in,surface_speed=ft/min,...": every quantity, in quantityKey order. fromText also takes
  // "metric", "inch", or either followed by overrides ("inch,power=kW"); nullopt and a reason naming
  // the item and the allowed values when an item is unknown.
  QString toText() const;
  static std::optional<ShopUnits> fromText(const QString& text, QString* error = nullptr);

  bool operator==(const ShopUnits&) const = default;

 private:
  static std::size_t index(Quantity q) { return static_cast<std::size_t>(q); }
  std::array<int, kQuantityCount> choice_{};
};

// Conversions of the values views receive into base units.
inline double perMinute(double per_second) {
  return 60.0 * per_second;
}
inline double cm3PerMinFromMm3PerS(double mm3_per_s) {
  return mm3_per_s * 60.0 / 1000.0;
}
inline double cm3PerMinFromCm3PerS(double cm3_per_s) {
  return cm3_per_s * 60.0;
}
inline double cm3PerSFromCm3PerMin(double cm3_per_min) {
  return cm3_per_min / 60.0;
}

}  // namespace mx::widgets
