#pragma once
// The Preferences dialog's shop-units page: one combo box per quantity (length, surface speed, feed
// rate, chip load, power, force, MRR), each item naming its exact factor to the base unit, and the
// "Metric" and "Inch" presets that set them all. The dialog only edits a ShopUnits value; the main
// window applies and remembers it when the dialog is accepted.
#include <QDialog>
#include <array>

#include "shop_units.h"

class QComboBox;
class QPushButton;

namespace mx::widgets {

class ShopUnitsDialog : public QDialog {
  Q_OBJECT
 public:
  explicit ShopUnitsDialog(QWidget* parent = nullptr);

  void setShopUnits(const ShopUnits& units);
  ShopUnits shopUnits() const;

  QComboBox* combo(Quantity q) const { return combos_[static_cast<std::size_t>(q)]; }  // "units_<key>"
  QPushButton* metricButton() const { return metric_; }                                // "units_metric"
  QPushButton* inchButton() const { return inch_; }                                    // "units_inch"

 private:
  static QString itemText(Quantity q, const UnitSpec& unit);

  std::array<QComboBox*, kQuantityCount> combos_{};
  QPushButton* metric_;
  QPushButton* inch_;
};

}  // namespace mx::widgets
