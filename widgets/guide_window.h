#pragma once
// The user guide in a window of its own beside the main window (not modal): the headings as a
// contents list on the left, the Markdown text with its pictures on the right, and a find field
// (Ctrl+F; Enter finds the next match, wrapping at the end). In-page links ("#glossary") go to their
// heading. Pictures wider than the text column are scaled down to it, keeping their aspect ratio, so
// that a 1920-pixel screenshot needs no horizontal scrolling. The source is any URL QTextBrowser
// reads, e.g. the guide compiled in as a Qt resource.
#include <QStringList>
#include <QUrl>
#include <QWidget>

class QLabel;
class QLineEdit;
class QTextBrowser;
class QTreeWidget;
class QTreeWidgetItem;

namespace mx::widgets {

class GuideWindow : public QWidget {
  Q_OBJECT
 public:
  explicit GuideWindow(const QUrl& source, QWidget* parent = nullptr);  // a top-level window

  QTextBrowser* browser() const { return browser_; }
  QStringList headings() const;           // of the contents list, in document order
  void showHeading(const QString& text);  // scrolls the heading to the top
  bool findNext(const QString& text);     // selects the next match after the cursor, wrapping; false if none
  // A link clicked in the text: "#heading-slug" shows that heading (GitHub's anchors), a web address
  // opens in the browser.
  void followLink(const QUrl& url);
  QLineEdit* findField() const { return find_; }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;  // the text column's width: fitImages

 private:
  void fillContents();
  void fitImages();
  void scrollToBlock(int block_number);

  QTextBrowser* browser_;
  QTreeWidget* contents_;
  QLineEdit* find_;
  QLabel* find_status_;
  int fitted_width_ = 0;  // the image width last applied (a resize to the same width does nothing)
};

}  // namespace mx::widgets
