#include "range_delegate.h"

#include <cmath>

#include "checked_spin_box.h"

namespace mx::widgets {

namespace {
constexpr char kOriginal[] = "mx_original";  // the value shown when the editor opened

// The name the editor's messages give the cell: its FieldNameRole, or its column header as a sentence's start.
QString fieldName(const QModelIndex& index) {
  QString name = index.data(RangeDelegate::FieldNameRole).toString();
  if (name.isEmpty()) name = index.model()->headerData(index.column(), Qt::Horizontal).toString();
  if (!name.isEmpty()) name[0] = name[0].toUpper();
  return name;
}

}  // namespace

QWidget* RangeDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                                     const QModelIndex& index) const {
  const QVariant minimum = index.data(MinimumRole);
  if (!minimum.isValid()) return QStyledItemDelegate::createEditor(parent, option, index);
  const int decimals = index.data(DecimalsRole).toInt();
  QAbstractSpinBox* editor = nullptr;
  if (decimals == 0) {
    auto* box = new CheckedSpinBox(parent);
    box->setRange(minimum.toInt(), index.data(MaximumRole).toInt());
    box->setSuffix(index.data(SuffixRole).toString());
    box->setFieldName(fieldName(index));
    editor = box;
  } else {
    auto* box = new CheckedDoubleSpinBox(parent);
    box->setDecimals(decimals);
    box->setRange(minimum.toDouble(), index.data(MaximumRole).toDouble());
    const QVariant step = index.data(StepRole);
    if (step.isValid()) box->setSingleStep(step.toDouble());
    box->setSuffix(index.data(SuffixRole).toString());
    box->setFieldName(fieldName(index));
    editor = box;
  }
  editor->setSpecialValueText(index.data(SpecialTextRole).toString());
  editor->setToolTip(index.data(Qt::ToolTipRole).toString());
  editor->setFrame(false);
  return editor;
}

void RangeDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
  const QVariant value = index.data(Qt::EditRole);
  editor->setProperty(kOriginal, value);
  if (auto* int_box = qobject_cast<QSpinBox*>(editor)) {
    int_box->setValue(value.isValid() ? value.toInt() : int_box->minimum());
  } else if (auto* double_box = qobject_cast<QDoubleSpinBox*>(editor)) {
    double_box->setValue(value.isValid() ? value.toDouble() : double_box->minimum());
  } else {
    QStyledItemDelegate::setEditorData(editor, index);
  }
}

void RangeDelegate::setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const {
  auto* spin = qobject_cast<QAbstractSpinBox*>(editor);
  if (!spin) return QStyledItemDelegate::setModelData(editor, model, index);
  spin->interpretText();
  const QVariant original = editor->property(kOriginal);
  const bool special = !spin->specialValueText().isEmpty();
  QVariant value;
  if (auto* int_box = qobject_cast<QSpinBox*>(editor)) {
    if (!(special && int_box->value() == int_box->minimum())) value = int_box->value();
  } else if (auto* double_box = qobject_cast<QDoubleSpinBox*>(editor)) {
    if (!(special && double_box->value() == double_box->minimum())) value = double_box->value();
    // Opening and closing the editor must not round a more precise stored value to the box's decimals.
    if (value.isValid() && original.isValid() &&
        std::abs(original.toDouble() - double_box->value()) <= 0.5 * std::pow(10.0, -double_box->decimals()))
      return;
  }
  if (value.isValid() == original.isValid() && (!value.isValid() || value.toDouble() == original.toDouble())) return;
  model->setData(index, value, Qt::EditRole);
}

}  // namespace mx::widgets
