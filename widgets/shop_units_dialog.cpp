#include "shop_units_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace mx::widgets {

ShopUnitsDialog::ShopUnitsDialog(QWidget* parent)
    : QDialog(parent), metric_(new QPushButton(tr("Metric"), this)), inch_(new QPushButton(tr("Inch"), this)) {
  setObjectName("preferencesDialog");
  setWindowTitle(tr("Preferences"));
  auto* group = new QGroupBox(tr("Shop units"), this);
  auto* note = new QLabel(tr("How every view, the status bar and the report show and accept values. The project "
                             "file does not change: it stays in mm, m/min, mm/min, W and N."),
                          group);
  note->setWordWrap(true);
  metric_->setObjectName("units_metric");
  metric_->setToolTip(tr("mm, m/min, mm/min, mm/tooth, W, N, cm\u00b3/min"));
  inch_->setObjectName("units_inch");
  inch_->setToolTip(tr("in, SFM, IPM, in/tooth, hp, lbf, in\u00b3/min"));
  auto* presets = new QHBoxLayout;
  presets->addWidget(new QLabel(tr("Presets:"), group));
  presets->addWidget(metric_);
  presets->addWidget(inch_);
  presets->addStretch(1);
  auto* form = new QFormLayout;
  form->setLabelAlignment(Qt::AlignRight);
  for (int i = 0; i < kQuantityCount; ++i) {
    const auto q = static_cast<Quantity>(i);
    auto* combo = new QComboBox(group);
    combo->setObjectName("units_" + ShopUnits::quantityKey(q));
    for (const UnitSpec& unit : ShopUnits::choices(q)) combo->addItem(itemText(q, unit), QString::fromLatin1(unit.key));
    combo->setToolTip(tr("The unit of %1 in every label and field").arg(ShopUnits::quantityName(q)));
    form->addRow(ShopUnits::quantityName(q) + ":", combo);
    combos_[static_cast<std::size_t>(i)] = combo;
  }
  auto* inner = new QVBoxLayout(group);
  inner->addWidget(note);
  inner->addLayout(presets);
  inner->addLayout(form);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  auto* outer = new QVBoxLayout(this);
  outer->addWidget(group);
  outer->addWidget(buttons);
  connect(metric_, &QPushButton::clicked, this, [this] { setShopUnits(ShopUnits::metric()); });
  connect(inch_, &QPushButton::clicked, this, [this] { setShopUnits(ShopUnits::inch()); });
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  setShopUnits(ShopUnits::metric());
}

// "hp (1 hp = 745.699872 W)": the exact factor to the base unit, so that the page documents itself.
QString ShopUnitsDialog::itemText(Quantity q, const UnitSpec& unit) {
  const UnitSpec& base = ShopUnits::choices(q).front();
  QString symbol = QString::fromUtf8(unit.symbol);
  if (unit.base_per_unit == 1.0) return symbol;
  return tr("%1 (1 %1 = %2 %3)")
      .arg(symbol, QString::number(unit.base_per_unit, 'g', 15), QString::fromUtf8(base.symbol));
}

void ShopUnitsDialog::setShopUnits(const ShopUnits& units) {
  for (int i = 0; i < kQuantityCount; ++i)
    combos_[static_cast<std::size_t>(i)]->setCurrentIndex(units.choice(static_cast<Quantity>(i)));
}

ShopUnits ShopUnitsDialog::shopUnits() const {
  ShopUnits units;
  for (int i = 0; i < kQuantityCount; ++i)
    units.setChoice(static_cast<Quantity>(i), combos_[static_cast<std::size_t>(i)]->currentIndex());
  return units;
}

}  // namespace mx::widgets
