#pragma once
// A layout that places its items in a row, left to right, and wraps to a new row where the next item
// does not fit the width, so that a row of buttons in a narrow dock stays whole instead of being cut
// off at the dock's edge. Items keep their size hints. The minimum height is that of the rows at the
// width last laid out (not a heightForWidth: in a scroll area that would size the whole page to its
// preferred height); a new row count asks the parent for a new layout.
#include <QLayout>
#include <QList>

namespace mx::widgets {

class FlowLayout : public QLayout {
 public:
  explicit FlowLayout(QWidget* parent = nullptr, int spacing = -1);
  ~FlowLayout() override;

  void addItem(QLayoutItem* item) override;
  int count() const override;
  QLayoutItem* itemAt(int index) const override;
  QLayoutItem* takeAt(int index) override;
  Qt::Orientations expandingDirections() const override { return {}; }
  QSize minimumSize() const override;  // the widest item, as tall as the rows at the last width
  QSize sizeHint() const override;     // all items on one row
  void setGeometry(const QRect& rect) override;

  int heightFor(int width) const;  // height of the rows at `width`, margins included
  int rowCount(int width) const;   // rows the items take at `width`

 private:
  int spacingOrStyle() const;
  // Lays the items out in `rect` (moving them when `apply`); returns the height used and the row count.
  int arrange(const QRect& rect, bool apply, int* rows = nullptr) const;

  QList<QLayoutItem*> items_;
  int width_ = -1;  // of the last setGeometry
};

}  // namespace mx::widgets
