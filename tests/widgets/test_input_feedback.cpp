// The input note: shown at once right under the field or table cell (above it at the window's bottom),
// one per window, gone after kInputNoteMs or when hidden.
#include <QLabel>
#include <QLineEdit>
#include <QStandardItemModel>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

#include "input_feedback.h"
#include "test_registry.h"

using mx::widgets::hideInputNote;
using mx::widgets::inputNote;
using mx::widgets::showInputNote;

namespace {

QRect globalRect(const QWidget* widget, const QRect& rect) {
  return {widget->mapToGlobal(rect.topLeft()), rect.size()};
}

}  // namespace

class TestInputFeedback : public QObject {
  Q_OBJECT
 private slots:
  void noteUnderOrAboveTheField_data() {
    QTest::addColumn<int>("fieldY");
    QTest::addColumn<bool>("below");
    QTest::newRow("top of the window") << 0 << true;
    QTest::newRow("middle") << 200 << true;
    QTest::newRow("bottom of the window") << 380 << false;
  }
  void noteUnderOrAboveTheField() {
    QFETCH(int, fieldY);
    QFETCH(bool, below);
    QWidget window;
    window.resize(600, 400);
    auto* field = new QLineEdit(&window);
    field->setGeometry(50, fieldY, 120, 20);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QCOMPARE(inputNote(field), nullptr);

    showInputNote(field, "Teeth must be a whole number from 1 to 100.");
    QLabel* note = inputNote(field);
    QVERIFY(note);
    QVERIFY(note->isVisible());
    QCOMPARE(note->text(), QString("Teeth must be a whole number from 1 to 100."));
    QCOMPARE(note->x(), 50);
    if (below) {
      QCOMPARE(note->y(), field->geometry().bottom() + 1);
    } else {
      QCOMPARE(note->geometry().bottom() + 1, field->y());
    }
    QVERIFY(window.rect().contains(note->geometry()));
    auto* timer = note->findChild<QTimer*>();
    QVERIFY(timer && timer->isActive());
    QCOMPARE(timer->interval(), mx::widgets::kInputNoteMs);

    hideInputNote(field);
    QVERIFY(!note->isVisible());
  }

  void oneNotePerWindowThatExpires() {
    QWidget window;
    window.resize(600, 400);
    auto* layout = new QVBoxLayout(&window);
    auto* first = new QLineEdit(&window);
    auto* second = new QLineEdit(&window);
    layout->addWidget(first);
    layout->addWidget(second);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    showInputNote(first, "first");
    showInputNote(second, "second");
    QLabel* note = inputNote(first);
    QCOMPARE(inputNote(second), note);
    QCOMPARE(window.findChildren<QLabel*>().size(), 1);
    QCOMPARE(note->text(), QString("second"));
    QCOMPARE(note->y(), second->geometry().bottom() + 1);
    note->findChild<QTimer*>()->start(10);
    QTRY_VERIFY(!note->isVisible());
  }

  void noteUnderACell() {
    QStandardItemModel model(5, 3);
    QTableView view;
    view.setModel(&model);
    view.resize(500, 300);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const QModelIndex index = model.index(1, 2);
    showInputNote(&view, index, "Stiffness k [N/µm] must be between 0.001 and 1000000.");
    QLabel* note = inputNote(&view);
    QVERIFY(note && note->isVisible());
    const QRect cell = globalRect(view.viewport(), view.visualRect(index));
    const QRect shown = globalRect(note, note->rect());
    QCOMPARE(shown.top(), cell.bottom() + 1);
    QVERIFY(shown.left() <= cell.right() && shown.right() >= cell.left());

    showInputNote(&view, QModelIndex(), "no cell");  // then under the view's top
    QCOMPARE(globalRect(note, note->rect()).top(), view.mapToGlobal(QPoint(0, 1)).y());
  }
};

MX_REGISTER_TEST(TestInputFeedback)
#include "test_input_feedback.moc"
