// A view or, in its place, why it does not apply and the action that makes it apply: the notice
// hides the view, shows its text and button (none without an action), the button is signalled, and
// the view comes back.
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include "notice_stack.h"
#include "test_registry.h"

using mx::widgets::NoticeStack;

class TestNoticeStack : public QObject {
  Q_OBJECT

 private slots:
  void noticeReplacesTheViewAndComesBack() {
    auto* view = new QLabel("plot");
    NoticeStack stack(view);
    stack.resize(600, 300);
    stack.show();
    QVERIFY(QTest::qWaitForWindowExposed(&stack));
    QVERIFY(!stack.noticeShown());
    QCOMPARE(stack.currentWidget(), view);
    stack.showNotice("This project has no Pareto study.", "Add a Pareto section");
    QVERIFY(stack.noticeShown() && !view->isVisible());
    QCOMPARE(stack.noticeText(), QString("This project has no Pareto study."));
    QVERIFY(stack.actionButton()->isVisible());
    QCOMPARE(stack.actionButton()->text(), QString("Add a Pareto section"));
    QSignalSpy triggered(&stack, &NoticeStack::actionTriggered);
    QTest::mouseClick(stack.actionButton(), Qt::LeftButton);
    QCOMPARE(triggered.count(), 1);
    stack.showNotice("The study needs a tool.");
    QVERIFY(!stack.actionButton()->isVisible());
    stack.showContent();
    QVERIFY(!stack.noticeShown() && view->isVisible());
    QCOMPARE(stack.noticeText(), QString());
  }
};

MX_REGISTER_TEST(TestNoticeStack)
#include "test_notice_stack.moc"
