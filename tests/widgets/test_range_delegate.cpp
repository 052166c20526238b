// The range delegate: its spin boxes name the cell by its FieldNameRole or its column header, and a
// value the box cannot take leaves the cell unchanged with the reason under it.
#include <QLabel>
#include <QStandardItemModel>
#include <QTableView>

#include "checked_spin_box.h"
#include "input_feedback.h"
#include "range_delegate.h"
#include "support/settle_events.h"
#include "test_registry.h"

using mx::widgets::RangeDelegate;

namespace {

// teeth 4 in [1, 100]; stiffness 5.59 in [0.001, 1e6] with a field name.
void fill(QStandardItemModel& model) {
  model.setHorizontalHeaderLabels({"teeth", "stiffness [N/µm]"});
  auto* teeth = new QStandardItem;
  teeth->setData(4, Qt::EditRole);
  teeth->setData(1.0, RangeDelegate::MinimumRole);
  teeth->setData(100.0, RangeDelegate::MaximumRole);
  teeth->setData(0, RangeDelegate::DecimalsRole);
  auto* stiffness = new QStandardItem;
  stiffness->setData(5.59, Qt::EditRole);
  stiffness->setData(0.001, RangeDelegate::MinimumRole);
  stiffness->setData(1e6, RangeDelegate::MaximumRole);
  stiffness->setData(4, RangeDelegate::DecimalsRole);
  stiffness->setData("Stiffness k [N/µm]", RangeDelegate::FieldNameRole);
  model.appendRow({teeth, stiffness});
}

using mx::test::settle;

}  // namespace

class TestRangeDelegate : public QObject {
  Q_OBJECT
 private slots:
  void editorsNameTheirCell() {
    QStandardItemModel model;
    fill(model);
    QTableView view;
    view.setModel(&model);
    view.setItemDelegate(new RangeDelegate(&view));
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.edit(model.index(0, 0));
    auto* teeth = dynamic_cast<mx::widgets::CheckedSpinBox*>(view.viewport()->findChild<QSpinBox*>());
    QVERIFY(teeth);
    QCOMPARE(teeth->fieldName(), QString("Teeth"));  // the header, as a sentence's start
    QCOMPARE(teeth->minimum(), 1);
    QTest::keyClick(teeth, Qt::Key_Escape);
    settle();
    view.edit(model.index(0, 1));
    auto* stiffness = dynamic_cast<mx::widgets::CheckedDoubleSpinBox*>(view.viewport()->findChild<QDoubleSpinBox*>());
    QVERIFY(stiffness);
    QCOMPARE(stiffness->fieldName(), QString("Stiffness k [N/µm]"));
  }

  void refusedInputLeavesTheCellWithTheReason() {
    QStandardItemModel model;
    fill(model);
    QTableView view;
    view.setModel(&model);
    view.setItemDelegate(new RangeDelegate(&view));
    view.resize(500, 300);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const QModelIndex index = model.index(0, 0);
    view.setCurrentIndex(index);
    view.edit(index);
    auto* box = view.viewport()->findChild<QSpinBox*>();
    QVERIFY(box);
    box->selectAll();
    QTest::keyClicks(box, "abc");
    QTest::keyClick(box, Qt::Key_Return);
    settle();
    QVERIFY(!view.viewport()->findChild<QSpinBox*>());  // committed and closed
    QCOMPARE(index.data(Qt::EditRole).toInt(), 4);
    const QLabel* note = mx::widgets::inputNote(&view);
    QVERIFY(note && note->isVisible());
    QCOMPARE(note->text(), QString("Teeth must be a whole number from 1 to 100; \"abc\" is not a number. "
                                   "The value stays 4."));
    const QRect cell(view.viewport()->mapToGlobal(view.visualRect(index).topLeft()), view.visualRect(index).size());
    QCOMPARE(note->mapToGlobal(QPoint(0, 0)).y(), cell.bottom() + 1);
  }
};

MX_REGISTER_TEST(TestRangeDelegate)
#include "test_range_delegate.moc"
