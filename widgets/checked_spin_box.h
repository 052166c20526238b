#pragma once
// Spin boxes that answer input they cannot take instead of dropping it silently. Text the plain box
// refuses (letters, a minus sign under a minimum of 0, a value out of range, too many decimals) stays
// in the box, and a note under it (input_feedback.h) names the field, the text and the range:
//   Stiffness k [N/µm] must be between 0.001 and 1000000; "-5" is below the minimum.
// When editing ends on text the box cannot take (Enter, focus out, a table committing its editor) the
// box keeps its value, as the plain box does, and the note says so. The next accepted keystroke hides
// the note.
#include <QDoubleSpinBox>
#include <QLocale>
#include <QSpinBox>

class QKeyEvent;

namespace mx::widgets {

// What a box takes, in the words of its notes.
struct SpinLimits {
  QString field;  // name and unit, e.g. "Stiffness k [N/µm]"
  double minimum = 0.0;
  double maximum = 0.0;
  int decimals = 0;  // 0: whole numbers
  QString special;   // the text shown at the minimum for "no value", if any
};

// Why `typed` (the box's text without prefix and suffix) is not a value of `limits`: "<field> must
// be between 0.001 and 1000000; "-5" is below the minimum." "" when it is one.
QString spinRefusal(const SpinLimits& limits, const QString& typed, const QLocale& locale);

template <class Box>
class CheckedBox : public Box {
 public:
  // Without keyboard tracking: the value changes when editing ends, so that text refused then leaves
  // the value from before the edit (typing 2000000 into [0, 1e6] passes through 200000).
  explicit CheckedBox(QWidget* parent = nullptr) : Box(parent) { this->setKeyboardTracking(false); }

  // The field's name with its unit for the notes; without a "[unit]" the box's suffix is added.
  void setFieldName(const QString& name) { field_ = name; }
  QString fieldName() const { return field_; }
  SpinLimits limits() const;

  QValidator::State validate(QString& text, int& pos) const override;
  void fixup(QString& text) const override;

 protected:
  void keyPressEvent(QKeyEvent* event) override;

 private:
  QString typed(const QString& text) const;  // without prefix, suffix and surrounding spaces
  QString shownValue() const;                // the box's value as the notes name it

  QString field_;
  bool typing_ = false;         // inside a keystroke that edits the text
  mutable bool ended_ = false;  // fixup has said that the box keeps its value
};

using CheckedSpinBox = CheckedBox<QSpinBox>;
using CheckedDoubleSpinBox = CheckedBox<QDoubleSpinBox>;
extern template class CheckedBox<QSpinBox>;
extern template class CheckedBox<QDoubleSpinBox>;

}  // namespace mx::widgets
