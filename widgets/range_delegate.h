#pragma once
// Spin-box editing for table models that publish their ranges through item-data roles: an integer
// or decimal spin box with the model's minimum, maximum, decimals and step. When the model gives a
// special text (e.g. "material's"), the minimum shows that text and stands for "no value"
// (setData with an invalid QVariant). Cells without a MinimumRole get the default editor. Input the
// box cannot take is answered at once under the cell (checked_spin_box.h), naming the field by its
// FieldNameRole, or else by its column header.
#include <QStyledItemDelegate>

namespace mx::widgets {

class RangeDelegate : public QStyledItemDelegate {
  Q_OBJECT
 public:
  enum Role {
    MinimumRole = Qt::UserRole + 100,  // double (display units); presence selects a spin box
    MaximumRole,                       // double
    DecimalsRole,                      // int; 0 = integer spin box
    StepRole,                          // double single step
    SpecialTextRole,                   // QString shown at the minimum = "no value"
    SuffixRole,                        // QString, e.g. " mm"
    FieldNameRole,                     // QString, name and unit for messages, e.g. "Stiffness k [N/µm]"
  };
  using QStyledItemDelegate::QStyledItemDelegate;

  QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option, const QModelIndex& index) const override;
  void setEditorData(QWidget* editor, const QModelIndex& index) const override;
  void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override;
};

}  // namespace mx::widgets
