#include "checked_spin_box.h"

#include <QKeyEvent>
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "input_feedback.h"

namespace mx::widgets {

namespace {

// A limit or value as the box would show it, without group separators and trailing zeros.
QString formatNumber(double value, int decimals, const QLocale& locale) {
  QLocale plain(locale);
  plain.setNumberOptions(QLocale::OmitGroupSeparator);
  if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;  // no "-0"
  QString text = plain.toString(value, 'f', decimals);
  if (decimals > 0) {
    while (text.endsWith('0')) text.chop(1);
    if (text.endsWith(plain.decimalPoint())) text.chop(plain.decimalPoint().size());
  }
  return text;
}

QString quoted(const QString& typed) {
  constexpr int kMaxChars = 24;  // pasted text may be long: the note names its start
  return "\"" + (typed.size() > kMaxChars ? typed.left(kMaxChars - 1) + QChar(0x2026) : typed) + "\"";
}

QString requirement(const SpinLimits& l, const QLocale& locale) {
  // With a special text the minimum stands for "no value": the smallest value is one step above.
  const double lowest = l.special.isEmpty() ? l.minimum : l.minimum + std::pow(10.0, -l.decimals);
  const QString lo = formatNumber(lowest, l.decimals, locale);
  const QString hi = formatNumber(l.maximum, l.decimals, locale);
  QString text = l.decimals == 0 ? QObject::tr("%1 must be a whole number from %2 to %3").arg(l.field, lo, hi)
                                 : QObject::tr("%1 must be between %2 and %3").arg(l.field, lo, hi);
  if (!l.special.isEmpty()) text += QObject::tr(", or \"%1\"").arg(l.special);
  return text;
}

int decimalsOf(const QString& typed, const QLocale& locale) {
  const qsizetype point = typed.indexOf(locale.decimalPoint());
  return point < 0 ? 0 : int(typed.size() - point - locale.decimalPoint().size());
}

// Why `typed` is no value of `l`; "" when it is one.
QString reason(const SpinLimits& l, const QString& typed, const QLocale& locale) {
  if (typed.isEmpty()) return QObject::tr("nothing was entered");
  bool ok = false;
  double value = locale.toDouble(typed, &ok);
  if (!ok) value = locale.toDouble(QString(typed).remove(locale.groupSeparator()), &ok);
  if (!ok) {
    if (typed == locale.negativeSign() && l.minimum >= 0.0)
      return QObject::tr("%1 is below the minimum").arg(quoted(typed));
    return QObject::tr("%1 is not a number").arg(quoted(typed));
  }
  const bool fraction = value != std::floor(value) || typed.contains(locale.decimalPoint());  // "2." too
  if (l.decimals == 0 && fraction) return QObject::tr("%1 is not a whole number").arg(quoted(typed));
  if (value < l.minimum) return QObject::tr("%1 is below the minimum").arg(quoted(typed));
  if (value > l.maximum) return QObject::tr("%1 is above the maximum").arg(quoted(typed));
  if (l.decimals > 0 && !typed.contains('e', Qt::CaseInsensitive) && decimalsOf(typed, locale) > l.decimals)
    return QObject::tr("%1 has more than %n decimal(s)", nullptr, l.decimals).arg(quoted(typed));
  return {};
}

}  // namespace

QString spinRefusal(const SpinLimits& limits, const QString& typed, const QLocale& locale) {
  const QString why = reason(limits, typed, locale);
  return why.isEmpty() ? QString() : requirement(limits, locale) + "; " + why + ".";
}

template <class Box>
SpinLimits CheckedBox<Box>::limits() const {
  SpinLimits l;
  l.field = field_.isEmpty() ? QObject::tr("The value") : field_;
  const QString unit = this->suffix().trimmed();
  if (!unit.isEmpty() && !l.field.contains('[')) l.field += " [" + unit + "]";
  l.minimum = this->minimum();
  l.maximum = this->maximum();
  if constexpr (std::is_same_v<Box, QDoubleSpinBox>) l.decimals = this->decimals();
  l.special = this->specialValueText();
  return l;
}

template <class Box>
QString CheckedBox<Box>::typed(const QString& text) const {
  QString t = text;
  if (!this->prefix().isEmpty() && t.startsWith(this->prefix())) t.remove(0, this->prefix().size());
  if (!this->suffix().isEmpty() && t.endsWith(this->suffix())) t.chop(this->suffix().size());
  return t.trimmed();
}

template <class Box>
QString CheckedBox<Box>::shownValue() const {
  const SpinLimits l = limits();
  if (!l.special.isEmpty() && this->value() == this->minimum()) return l.special;
  return formatNumber(this->value(), l.decimals, this->locale()) + this->suffix();
}

template <class Box>
QValidator::State CheckedBox<Box>::validate(QString& text, int& pos) const {
  const QValidator::State state = Box::validate(text, pos);
  if (state != QValidator::Invalid) {
    if (state == QValidator::Acceptable) ended_ = false;  // the box shows a value again
    if (typing_) hideInputNote(this);
    return state;
  }
  const QString entered = typed(text);
  const QString special = this->specialValueText();
  // The start of the special text ("mat" of "material's") is on its way to a value.
  if (!special.isEmpty() && special.startsWith(entered, Qt::CaseInsensitive)) return QValidator::Intermediate;
  const QString why = spinRefusal(limits(), entered, this->locale());
  if (why.isEmpty()) return state;
  // Kept, not dropped: the note can name what was typed; the box still never takes it as its value.
  if (!ended_) showInputNote(const_cast<CheckedBox*>(this), why);
  return QValidator::Intermediate;
}

template <class Box>
void CheckedBox<Box>::fixup(QString& text) const {
  Box::fixup(text);
  const QString why = spinRefusal(limits(), typed(text), this->locale());
  if (why.isEmpty()) return;
  showInputNote(const_cast<CheckedBox*>(this), why + " " + QObject::tr("The value stays %1.").arg(shownValue()));
  ended_ = true;
}

template <class Box>
void CheckedBox<Box>::keyPressEvent(QKeyEvent* event) {
  static constexpr Qt::Key kCommitKeys[] = {Qt::Key_Return, Qt::Key_Enter, Qt::Key_Escape, Qt::Key_Tab,
                                            Qt::Key_Backtab};
  typing_ = !event->text().isEmpty() &&
            std::find(std::begin(kCommitKeys), std::end(kCommitKeys), Qt::Key(event->key())) == std::end(kCommitKeys);
  if (typing_) ended_ = false;
  Box::keyPressEvent(event);
  typing_ = false;
}

template class CheckedBox<QSpinBox>;
template class CheckedBox<QDoubleSpinBox>;

}  // namespace mx::widgets
