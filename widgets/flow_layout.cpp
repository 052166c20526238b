#include "flow_layout.h"

#include <QStyle>
#include <QWidget>
#include <algorithm>

namespace mx::widgets {

FlowLayout::FlowLayout(QWidget* parent, int spacing) : QLayout(parent) {
  if (spacing >= 0) setSpacing(spacing);
}

FlowLayout::~FlowLayout() {
  while (QLayoutItem* item = takeAt(0)) delete item;
}

void FlowLayout::addItem(QLayoutItem* item) {
  items_.append(item);
}

int FlowLayout::count() const {
  return static_cast<int>(items_.size());
}

QLayoutItem* FlowLayout::itemAt(int index) const {
  return items_.value(index);
}

QLayoutItem* FlowLayout::takeAt(int index) {
  return index >= 0 && index < items_.size() ? items_.takeAt(index) : nullptr;
}

int FlowLayout::spacingOrStyle() const {
  if (spacing() >= 0) return spacing();
  const QWidget* parent = parentWidget();
  return parent ? parent->style()->pixelMetric(QStyle::PM_LayoutHorizontalSpacing, nullptr, parent) : 6;
}

int FlowLayout::heightFor(int width) const {
  return arrange(QRect(0, 0, width, 0), false);
}

int FlowLayout::rowCount(int width) const {
  int rows = 0;
  arrange(QRect(0, 0, width, 0), false, &rows);
  return rows;
}

QSize FlowLayout::minimumSize() const {
  QSize size;
  for (const QLayoutItem* item : items_)
    if (!item->isEmpty()) size = size.expandedTo(item->sizeHint());  // items keep their size hints
  const QMargins m = contentsMargins();
  size += QSize(m.left() + m.right(), m.top() + m.bottom());
  return width_ > 0 ? QSize(size.width(), std::max(size.height(), heightFor(width_))) : size;
}

QSize FlowLayout::sizeHint() const {
  int width = 0, height = 0;
  for (const QLayoutItem* item : items_) {
    if (item->isEmpty()) continue;
    width += item->sizeHint().width() + (width > 0 ? spacingOrStyle() : 0);
    height = std::max(height, item->sizeHint().height());
  }
  const QMargins m = contentsMargins();
  return QSize(width + m.left() + m.right(), std::max(height + m.top() + m.bottom(), minimumSize().height()));
}

void FlowLayout::setGeometry(const QRect& rect) {
  QLayout::setGeometry(rect);
  const int rows = rowCount(width_);
  width_ = rect.width();
  arrange(rect, true);
  if (rowCount(width_) != rows) invalidate();  // the parent lays out again for the new height
}

int FlowLayout::arrange(const QRect& rect, bool apply, int* rows) const {
  const QRect area = rect.marginsRemoved(contentsMargins());
  const int gap = spacingOrStyle();
  int x = area.x(), y = area.y(), row_height = 0, row_count = 0;
  for (QLayoutItem* item : items_) {
    if (item->isEmpty()) continue;  // a hidden widget
    const QSize size = item->sizeHint().boundedTo(QSize(area.width(), QWIDGETSIZE_MAX));
    if (x > area.x() && x + size.width() > area.right() + 1) {  // wrap
      x = area.x();
      y += row_height + gap;
      row_height = 0;
    }
    if (x == area.x()) ++row_count;
    if (apply) item->setGeometry(QRect(QPoint(x, y), size));
    x += size.width() + gap;
    row_height = std::max(row_height, size.height());
  }
  if (rows) *rows = row_count;
  const QMargins m = contentsMargins();
  return y + row_height - rect.y() + m.bottom();
}

}  // namespace mx::widgets
