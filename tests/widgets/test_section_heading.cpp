// A section's caption (widgets/section_heading.h): bold, in the parent given, and wrapped, so that a
// narrow dock shows all of it: at 60 px a two-word caption needs two lines.
#include <QLabel>
#include <QWidget>
#include <memory>

#include "section_heading.h"
#include "test_registry.h"

class TestSectionHeading : public QObject {
  Q_OBJECT

 private slots:
  void boldWrappedInItsParent() {
    QWidget parent;
    QLabel* label = mx::widgets::sectionHeading("Binding at q", &parent);
    QCOMPARE(label->parent(), &parent);
    QCOMPARE(label->text(), QString("Binding at q"));
    QVERIFY(label->font().bold());
    QVERIFY(!parent.font().bold());
    QVERIFY(label->wordWrap());
    const int one_line = label->fontMetrics().height();
    QVERIFY2(label->heightForWidth(60) >= 2 * one_line,
             qPrintable(QString("%1 px for %2 px lines").arg(label->heightForWidth(60)).arg(one_line)));
  }

  void withoutParent() {
    const std::unique_ptr<QLabel> label(mx::widgets::sectionHeading("Selected q"));
    QVERIFY(label->parent() == nullptr);
    QVERIFY(label->font().bold());
  }
};

MX_REGISTER_TEST(TestSectionHeading)
#include "test_section_heading.moc"
