#include "indicator_gauge.h"

#include <QPainter>
#include <algorithm>
#include <cmath>

namespace mx::widgets {

IndicatorGauge::IndicatorGauge(const QString& symbol, const QString& description, double threshold, QWidget* parent)
    : QWidget(parent), symbol_(symbol), threshold_(threshold) {
  setToolTip(description);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void IndicatorGauge::setThreshold(double threshold) {
  threshold_ = threshold;
  update();
}

void IndicatorGauge::setValue(double value) {
  value_ = std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
  update();
}

void IndicatorGauge::clear() {
  value_.reset();
  update();
}

QString IndicatorGauge::text() const {
  const QString value = value_ ? QString::number(*value_, 'f', 3) : QStringLiteral("\u2013");
  const QString verdict = !value_ ? QString() : exceeded() ? tr("  chatter") : tr("  ok");
  return tr("%1 = %2   (chatter \u2265 %3)%4").arg(symbol_, value).arg(threshold_, 0, 'f', 2).arg(verdict);
}

QSize IndicatorGauge::sizeHint() const {
  const QFontMetrics fm(font());
  return {std::max(240, fm.horizontalAdvance(text()) + 16), fm.height() * 2 + 14};
}

QSize IndicatorGauge::minimumSizeHint() const {
  const QFontMetrics fm(font());
  return {160, fm.height() * 2 + 14};
}

void IndicatorGauge::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QFontMetrics fm(font());
  const QColor state = !value_ ? palette().color(QPalette::Mid) : exceeded() ? alarmColor() : okColor();

  p.setPen(value_ ? state.darker(130) : palette().color(QPalette::WindowText));
  p.drawText(QRect(0, 0, width(), fm.height() + 2), Qt::AlignLeft | Qt::AlignVCenter, text());

  // Bar from 0 to twice the threshold (values beyond are drawn full).
  const QRectF bar(1.0, fm.height() + 5.0, width() - 2.0, height() - fm.height() - 7.0);
  p.setPen(QPen(palette().color(QPalette::Mid), 1.0));
  p.setBrush(palette().color(QPalette::Base));
  p.drawRoundedRect(bar, 3, 3);
  const double full = threshold_ > 0.0 ? 2.0 * threshold_ : 1.0;
  if (value_) {
    const double fraction = std::clamp(*value_ / full, 0.0, 1.0);
    p.setPen(Qt::NoPen);
    p.setBrush(state);
    p.drawRoundedRect(QRectF(bar.left(), bar.top(), bar.width() * fraction, bar.height()), 3, 3);
  }
  const double x = bar.left() + bar.width() * std::clamp(threshold_ / full, 0.0, 1.0);
  p.setPen(QPen(palette().color(QPalette::WindowText), 2.0));
  p.drawLine(QPointF(x, bar.top() - 2.0), QPointF(x, bar.bottom() + 2.0));
}

}  // namespace mx::widgets
