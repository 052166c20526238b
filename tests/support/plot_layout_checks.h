#pragma once
// Layout checks of a laid-out QCustomPlot for the widget tests (issue 24, item 8): no legend over the
// data, no legend name cut, value-axis tick labels apart. Each returns what is wrong, or an empty string.
#include <qcustomplot.h>

#include <QFontMetrics>
#include <QList>
#include <QString>
#include <QtGlobal>
#include <cmath>

namespace mx::test {

inline QList<QCPLegend*> legendsOf(const QCustomPlot* plot) {
  QList<QCPLegend*> legends;
  for (QCPLayoutElement* element : plot->plotLayout()->elements(true))
    if (auto* legend = qobject_cast<QCPLegend*>(element)) legends << legend;
  return legends;
}

inline QString rectText(const QRect& r) {
  return QString("%1x%2+%3+%4").arg(r.width()).arg(r.height()).arg(r.x()).arg(r.y());
}

// No legend meets an axis rect (its data, axes and tick labels); every entry is at least as wide as its
// icon and name need, and inside the plot.
inline QString legendProblem(const QCustomPlot* plot) {
  for (const QCPLegend* legend : legendsOf(plot)) {
    for (const QCPAxisRect* rect : plot->axisRects())
      if (legend->outerRect().intersects(rect->outerRect()))
        return QString("legend %1 over axis rect %2").arg(rectText(legend->outerRect()), rectText(rect->outerRect()));
    for (int i = 0; i < legend->itemCount(); ++i) {
      const QCPAbstractLegendItem* item = legend->item(i);
      if (!item) continue;
      auto* entry = qobject_cast<QCPPlottableLegendItem*>(legend->item(i));
      const QString name = entry ? entry->plottable()->name() : QString::number(i);
      if (item->outerRect().width() < item->minimumOuterSizeHint().width())
        return QString("\"%1\" cut: %2 px of %3")
            .arg(name)
            .arg(item->outerRect().width())
            .arg(item->minimumOuterSizeHint().width());
      if (!plot->viewport().contains(item->outerRect()))
        return QString("\"%1\" at %2 outside the plot").arg(name, rectText(item->outerRect()));
    }
  }
  return {};
}

// Every title or caption at least as wide as its text needs.
inline QString captionProblem(const QCustomPlot* plot) {
  for (const QCPLayoutElement* element : plot->plotLayout()->elements(true))
    if (const auto* text = qobject_cast<const QCPTextElement*>(element)) {
      const int needed = element->minimumOuterSizeHint().width();  // protected in QCPTextElement
      if (element->outerRect().width() < needed)
        return QString("\"%1\" cut: %2 px of %3").arg(text->text()).arg(element->outerRect().width()).arg(needed);
    }
  return {};
}

// The tick labels of a value (vertical) axis at least a label's height plus `gap` px apart.
inline QString tickLabelProblem(const QCPAxis* axis, int gap = 4) {
  const QVector<double> ticks = axis->tickVector();
  const int needed = QFontMetrics(axis->tickLabelFont()).height() + gap;
  for (int i = 1; i < ticks.size(); ++i) {
    const double apart = std::abs(axis->coordToPixel(ticks[i]) - axis->coordToPixel(ticks[i - 1]));
    if (apart < needed)
      return QString("\"%1\": ticks %2 and %3 only %4 px apart")
          .arg(axis->label())
          .arg(ticks[i - 1])
          .arg(ticks[i])
          .arg(apart);
  }
  return {};
}

// Counts, while it lives, QCustomPlot's "layouting aborted" messages: QCPLayout::getSectionSizes gives up
// on a row or column whose maximum is below its minimum, and the elements keep a stale geometry. The
// messages still reach the handler installed before it.
class LayoutAbortCounter {
 public:
  LayoutAbortCounter() {
    aborts_ = 0;
    previous_ = qInstallMessageHandler(&LayoutAbortCounter::handle);
  }
  ~LayoutAbortCounter() { qInstallMessageHandler(previous_); }
  LayoutAbortCounter(const LayoutAbortCounter&) = delete;
  LayoutAbortCounter& operator=(const LayoutAbortCounter&) = delete;
  int aborts() const { return aborts_; }

 private:
  static void handle(QtMsgType type, const QMessageLogContext& context, const QString& text) {
    if (text.contains(QLatin1String("layouting aborted"))) ++aborts_;
    if (previous_) previous_(type, context, text);
  }
  static inline int aborts_ = 0;
  static inline QtMessageHandler previous_ = nullptr;
};

}  // namespace mx::test
