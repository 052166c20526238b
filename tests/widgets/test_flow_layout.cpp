// FlowLayout: buttons stay on one row while they fit, wrap to more rows in a narrower widget, and are
// never cut off or overlapping; the minimum height follows the rows at the width laid out; hidden
// widgets take no room.
#include <QPushButton>
#include <QWidget>

#include "flow_layout.h"
#include "test_registry.h"

using mx::widgets::FlowLayout;

namespace {
constexpr int kSpacing = 6;

// Five buttons of the tool library's, each 100 x 30, no margins.
QList<QPushButton*> fill(QWidget& host, FlowLayout* layout) {
  QList<QPushButton*> buttons;
  for (const char* text : {"Add tool", "Duplicate", "Remove", "Import library...", "Export library..."}) {
    auto* b = new QPushButton(text, &host);
    b->setFixedSize(100, 30);
    layout->addWidget(b);
    buttons << b;
  }
  layout->setContentsMargins(0, 0, 0, 0);
  return buttons;
}
}  // namespace

class TestFlowLayout : public QObject {
  Q_OBJECT
 private slots:
  void wrapsWhereTheNextButtonDoesNotFit_data() {
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("rows");
    QTest::newRow("all on one row") << 5 * 100 + 4 * kSpacing << 1;
    QTest::newRow("one pixel short") << 5 * 100 + 4 * kSpacing - 1 << 2;
    QTest::newRow("three per row") << 3 * 100 + 2 * kSpacing << 2;
    QTest::newRow("two per row") << 2 * 100 + kSpacing << 3;
    QTest::newRow("one per row") << 100 << 5;
    QTest::newRow("narrower than a button") << 60 << 5;
  }
  void wrapsWhereTheNextButtonDoesNotFit() {
    QFETCH(int, width);
    QFETCH(int, rows);
    QWidget host;
    auto* layout = new FlowLayout(&host, kSpacing);
    const QList<QPushButton*> buttons = fill(host, layout);
    QCOMPARE(layout->rowCount(width), rows);
    const int height = layout->heightFor(width);
    QCOMPARE(height, rows * 30 + (rows - 1) * kSpacing);
    host.resize(width, height);
    layout->setGeometry(QRect(0, 0, width, height));
    QCOMPARE(layout->minimumSize().height(), height);
    for (QPushButton* b : buttons) {
      QVERIFY2(b->geometry().bottom() < height, qPrintable(b->text()));
      QCOMPARE(b->width(), 100);  // whole, never squeezed
      if (width >= 100) QVERIFY2(b->geometry().right() < width, qPrintable(b->text()));
      for (QPushButton* other : buttons)
        if (other != b) QVERIFY(!b->geometry().intersects(other->geometry()));
    }
  }

  void sizeHintIsOneRowAndMinimumTheWidestButton() {
    QWidget host;
    auto* layout = new FlowLayout(&host, kSpacing);
    const QList<QPushButton*> buttons = fill(host, layout);
    QCOMPARE(layout->sizeHint(), QSize(5 * 100 + 4 * kSpacing, 30));
    QCOMPARE(layout->minimumSize(), QSize(100, 30));
    QVERIFY(!layout->hasHeightForWidth());  // in a scroll area: the page keeps its minimum height
    buttons[1]->hide();
    QCOMPARE(layout->sizeHint(), QSize(4 * 100 + 3 * kSpacing, 30));
    QCOMPARE(layout->rowCount(4 * 100 + 3 * kSpacing), 1);
    QCOMPARE(layout->count(), 5);
    delete layout->takeAt(0);
    QCOMPARE(layout->count(), 4);
    QCOMPARE(layout->takeAt(7), nullptr);
  }
};

MX_REGISTER_TEST(TestFlowLayout)
#include "test_flow_layout.moc"
