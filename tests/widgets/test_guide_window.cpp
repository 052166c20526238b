// The guide window on a small Markdown file: the headings as a nested contents list, a heading shown
// at the top on request and through an in-page link, find with wrap-around, and a picture wider than
// the text column scaled down to it at its aspect ratio.
#include <QFile>
#include <QImage>
#include <QLineEdit>
#include <QScrollBar>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextFragment>
#include <QTreeWidget>

#include "guide_window.h"
#include "test_registry.h"

using mx::widgets::GuideWindow;

namespace {
// A guide with three levels of headings, long sections and a 1600 x 400 picture.
QUrl writeGuide(const QTemporaryDir& dir) {
  QImage picture(1600, 400, QImage::Format_RGB32);
  picture.fill(Qt::darkCyan);
  picture.save(dir.filePath("wide.png"));
  QString text = "# The guide\n\nIntro about stability lobes.\n\n## First section\n\n![a wide picture](wide.png)\n\n";
  for (int i = 0; i < 60; ++i) text += QString("Filler line %1 of the first section.\n\n").arg(i);
  text += "### A subsection\n\nThe needle is here.\n\n## Second section\n\nSee [the first](#first-section).\n\n";
  for (int i = 0; i < 60; ++i) text += QString("Filler line %1 of the second section.\n\n").arg(i);
  QFile file(dir.filePath("guide.md"));
  file.open(QIODevice::WriteOnly);
  file.write(text.toUtf8());
  return QUrl::fromLocalFile(dir.filePath("guide.md"));
}

QTextImageFormat firstPicture(const QTextBrowser* browser) {
  for (QTextBlock block = browser->document()->begin(); block.isValid(); block = block.next())
    for (auto it = block.begin(); !it.atEnd(); ++it)
      if (it.fragment().charFormat().isImageFormat()) return it.fragment().charFormat().toImageFormat();
  return {};
}

QString cursorBlock(const QTextBrowser* browser) {
  return browser->textCursor().block().text();
}
}  // namespace

class TestGuideWindow : public QObject {
  Q_OBJECT
 private slots:
  void headingsFormANestedContentsList() {
    QTemporaryDir dir;
    GuideWindow window(writeGuide(dir));
    QCOMPARE(window.headings(), QStringList({"The guide", "First section", "A subsection", "Second section"}));
    auto* contents = window.findChild<QTreeWidget*>("guideContents");
    QCOMPARE(contents->topLevelItemCount(), 1);
    QCOMPARE(contents->topLevelItem(0)->childCount(), 2);
    QCOMPARE(contents->topLevelItem(0)->child(0)->child(0)->text(0), QString("A subsection"));
    QVERIFY(window.browser()->toPlainText().contains("Intro about stability lobes."));
    QVERIFY(window.isWindow());
  }

  void aHeadingIsShownAtTheTop() {
    QTemporaryDir dir;
    GuideWindow window(writeGuide(dir));
    window.resize(900, 600);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.showHeading("Second section");
    QCOMPARE(cursorBlock(window.browser()), QString("Second section"));
    const int second = window.browser()->verticalScrollBar()->value();
    QVERIFY(second > 0);
    window.followLink(QUrl("#first-section"));
    QCOMPARE(cursorBlock(window.browser()), QString("First section"));
    QVERIFY(window.browser()->verticalScrollBar()->value() < second);
    window.followLink(QUrl("#no-such-heading"));  // nothing happens
    QCOMPARE(cursorBlock(window.browser()), QString("First section"));
  }

  void findSelectsTheNextMatchAndWraps() {
    QTemporaryDir dir;
    GuideWindow window(writeGuide(dir));
    QVERIFY(window.findNext("needle"));
    QCOMPARE(window.browser()->textCursor().selectedText(), QString("needle"));
    QVERIFY(window.findNext("NEEDLE"));  // from the end: wraps to the same match, any case
    QCOMPARE(cursorBlock(window.browser()), QString("The needle is here."));
    QVERIFY(!window.findNext("haystack"));
    QVERIFY(window.findField()->placeholderText().contains("Ctrl+F"));
  }

  void aWidePictureIsScaledToTheColumn() {
    QTemporaryDir dir;
    GuideWindow window(writeGuide(dir));
    window.resize(1000, 700);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const int column = window.browser()->viewport()->width();
    QTRY_VERIFY(firstPicture(window.browser()).width() > 0);
    const QTextImageFormat picture = firstPicture(window.browser());
    QVERIFY2(picture.width() <= column && picture.width() > column / 2.0,
             qPrintable(QString("picture %1 px in a %2 px column").arg(picture.width()).arg(column)));
    QVERIFY(!picture.hasProperty(QTextFormat::ImageHeight));  // the height follows at 4:1
  }
};

MX_REGISTER_TEST(TestGuideWindow)
#include "test_guide_window.moc"
