#pragma once
// The shop units of one main window (shop_units.h), shared by its views: they convert and label
// through it and follow changed(). The engine stays SI and the project file shop-metric; only what the
// views show and accept changes. The length accessors are the mm/inch part of it.
#include <QObject>
#include <QString>
#include <type_traits>

#include "shop_units.h"

namespace mx::widgets {

class DisplayUnits : public QObject {
  Q_OBJECT
 public:
  enum class Length { Millimetre, Inch };
  explicit DisplayUnits(QObject* parent = nullptr) : QObject(parent) {}

  const ShopUnits& shop() const { return shop_; }
  void setShop(const ShopUnits& shop) {
    if (shop == shop_) return;
    shop_ = shop;
    emit changed();
  }
  // The shop units of `units`, metric when there is none (a view without units shows the base units).
  static const ShopUnits& of(const DisplayUnits* units) {
    static const ShopUnits metric = ShopUnits::metric();
    return units ? units->shop_ : metric;
  }

  Length length() const { return shop_.choice(Quantity::Length) == 1 ? Length::Inch : Length::Millimetre; }
  void setLength(Length length) {
    ShopUnits shop = shop_;
    shop.setChoice(Quantity::Length, length == Length::Inch ? 1 : 0);
    setShop(shop);
  }
  // mm -> display value and back.
  double fromMm(double mm) const { return shop_.fromBase(Quantity::Length, mm); }
  double toMm(double value) const { return shop_.toBase(Quantity::Length, value); }
  QString lengthSuffix() const { return shop_.symbol(Quantity::Length); }
  int lengthDecimals() const { return shop_.decimals(Quantity::Length); }

 signals:
  void changed();

 private:
  ShopUnits shop_;
};

// Points `current` at `units` and runs `refresh` (a member function of `receiver`, or a callable) now
// and after every change of them; the receiver's connections to the previous units are dropped.
// nullptr units: metric, and no updates.
template <class Receiver, class Pointer, class Refresh>  // Pointer: DisplayUnits* or QPointer<DisplayUnits>
void followUnits(Receiver* receiver, Pointer& current, DisplayUnits* units, Refresh refresh) {
  if (current) QObject::disconnect(current, nullptr, receiver, nullptr);
  current = units;
  if (current) QObject::connect(current, &DisplayUnits::changed, receiver, refresh);
  if constexpr (std::is_member_function_pointer_v<Refresh>) {
    (receiver->*refresh)();
  } else {
    refresh();
  }
}

}  // namespace mx::widgets
