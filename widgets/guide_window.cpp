#include "guide_window.h"

#include <QAbstractTextDocumentLayout>
#include <QDesktopServices>
#include <QEvent>
#include <QHBoxLayout>
#include <QImageReader>
#include <QLabel>
#include <QLineEdit>
#include <QScrollBar>
#include <QShortcut>
#include <QSplitter>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTextFragment>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <vector>

namespace mx::widgets {

namespace {
constexpr int kBlockRole = Qt::UserRole;  // a contents entry's block number in the document
constexpr int kDefaultImageWidth = 900;   // before the window has a size

// GitHub's anchor of a heading: lower case, spaces as hyphens, other punctuation dropped.
QString slug(const QString& heading) {
  QString out;
  for (const QChar c : heading.toLower())
    if (c.isLetterOrNumber() || c == '-' || c == '_')
      out += c;
    else if (c == ' ')
      out += '-';
  return out;
}

// The file behind a picture's URL (a Qt resource or a local file), for its natural size.
QString imagePath(const QUrl& url) {
  if (url.scheme() == "qrc") return ":" + url.path();
  return url.isLocalFile() ? url.toLocalFile() : url.toString();
}
}  // namespace

GuideWindow::GuideWindow(const QUrl& source, QWidget* parent)
    : QWidget(parent, Qt::Window),
      browser_(new QTextBrowser(this)),
      contents_(new QTreeWidget(this)),
      find_(new QLineEdit(this)),
      find_status_(new QLabel(this)) {
  setObjectName("guideWindow");
  setWindowTitle(tr("MillExpert user guide"));
  browser_->setObjectName("guideText");
  browser_->setOpenLinks(false);                    // followLink: in-page links need the headings' slugs
  browser_->document()->setUndoRedoEnabled(false);  // the picture scaling edits the document
  browser_->setSource(source, QTextDocument::MarkdownResource);
  contents_->setObjectName("guideContents");
  contents_->setHeaderHidden(true);
  contents_->setToolTip(tr("The guide's sections: click one to show it"));
  find_->setObjectName("guideFind");
  find_->setPlaceholderText(tr("Find in the guide (Ctrl+F, Enter for the next match)"));
  find_->setClearButtonEnabled(true);

  auto* find_bar = new QHBoxLayout;
  find_bar->addWidget(new QLabel(tr("Find:"), this));
  find_bar->addWidget(find_, 1);
  find_bar->addWidget(find_status_);
  auto* splitter = new QSplitter(this);
  splitter->addWidget(contents_);
  splitter->addWidget(browser_);
  splitter->setStretchFactor(1, 1);
  splitter->setSizes({360, 840});
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(find_bar);
  layout->addWidget(splitter, 1);

  connect(new QShortcut(QKeySequence::Find, this), &QShortcut::activated, this, [this] {
    find_->setFocus();
    find_->selectAll();
  });
  connect(find_, &QLineEdit::returnPressed, this, [this] { findNext(find_->text()); });
  connect(find_, &QLineEdit::textChanged, find_status_, &QLabel::clear);
  connect(browser_, &QTextBrowser::anchorClicked, this, &GuideWindow::followLink);
  connect(contents_, &QTreeWidget::itemClicked, this,
          [this](QTreeWidgetItem* item) { scrollToBlock(item->data(0, kBlockRole).toInt()); });
  connect(contents_, &QTreeWidget::itemActivated, this,
          [this](QTreeWidgetItem* item) { scrollToBlock(item->data(0, kBlockRole).toInt()); });
  fillContents();
  fitImages();
  browser_->viewport()->installEventFilter(this);
  resize(1200, 860);
}

// The Markdown headings (#, ##, ###) as a tree: each under the nearest heading of a higher level.
void GuideWindow::fillContents() {
  contents_->clear();
  std::vector<std::pair<int, QTreeWidgetItem*>> parents;  // (level, item), levels increasing
  for (QTextBlock block = browser_->document()->begin(); block.isValid(); block = block.next()) {
    const int level = block.blockFormat().headingLevel();
    if (level <= 0) continue;
    while (!parents.empty() && parents.back().first >= level) parents.pop_back();
    auto* item = parents.empty() ? new QTreeWidgetItem(contents_) : new QTreeWidgetItem(parents.back().second);
    item->setText(0, block.text());
    item->setToolTip(0, block.text());  // long headings are elided in the list
    item->setData(0, kBlockRole, block.blockNumber());
    parents.emplace_back(level, item);
  }
  contents_->expandAll();
}

QStringList GuideWindow::headings() const {
  QStringList texts;
  for (QTreeWidgetItemIterator it(contents_); *it; ++it) texts << (*it)->text(0);
  return texts;
}

void GuideWindow::showHeading(const QString& text) {
  for (QTreeWidgetItemIterator it(contents_); *it; ++it)
    if ((*it)->text(0) == text) {
      contents_->setCurrentItem(*it);
      scrollToBlock((*it)->data(0, kBlockRole).toInt());
      return;
    }
}

void GuideWindow::scrollToBlock(int block_number) {
  const QTextBlock block = browser_->document()->findBlockByNumber(block_number);
  if (!block.isValid()) return;
  browser_->setTextCursor(QTextCursor(block));
  const QRectF rect = browser_->document()->documentLayout()->blockBoundingRect(block);
  browser_->verticalScrollBar()->setValue(int(rect.top()));
}

void GuideWindow::followLink(const QUrl& url) {
  if (url.scheme() == "http" || url.scheme() == "https" || url.scheme() == "mailto") {
    QDesktopServices::openUrl(url);
    return;
  }
  if (!url.path().isEmpty() || url.fragment().isEmpty()) return;  // the guide links to no other page
  for (QTreeWidgetItemIterator it(contents_); *it; ++it)
    if (slug((*it)->text(0)) == url.fragment()) {
      contents_->setCurrentItem(*it);
      scrollToBlock((*it)->data(0, kBlockRole).toInt());
      return;
    }
}

bool GuideWindow::findNext(const QString& text) {
  if (text.isEmpty()) return false;
  bool found = browser_->find(text);
  if (!found) {  // wrap around: from the start once more
    browser_->moveCursor(QTextCursor::Start);
    found = browser_->find(text);
  }
  find_status_->setText(found ? QString() : tr("not found"));
  return found;
}

bool GuideWindow::eventFilter(QObject* watched, QEvent* event) {
  if (watched == browser_->viewport() && event->type() == QEvent::Resize) fitImages();
  return QWidget::eventFilter(watched, event);
}

// Each picture at its natural width, or at the text column's width when that is narrower.
void GuideWindow::fitImages() {
  const int column = browser_->viewport()->width() - 2 * int(browser_->document()->documentMargin()) - 8;
  const int width = column > 300 ? column : kDefaultImageWidth;  // laid out, or not yet
  if (width == fitted_width_) return;
  fitted_width_ = width;
  struct Picture {
    int position, length;
    QTextImageFormat format;
  };
  std::vector<Picture> pictures;
  for (QTextBlock block = browser_->document()->begin(); block.isValid(); block = block.next())
    for (auto it = block.begin(); !it.atEnd(); ++it) {
      const QTextFragment fragment = it.fragment();
      if (fragment.isValid() && fragment.charFormat().isImageFormat())
        pictures.push_back({fragment.position(), fragment.length(), fragment.charFormat().toImageFormat()});
    }
  for (Picture& p : pictures) {
    const QSize natural = QImageReader(imagePath(browser_->source().resolved(QUrl(p.format.name())))).size();
    if (!natural.isValid()) continue;
    p.format.setWidth(std::min(natural.width(), width));
    p.format.clearProperty(QTextFormat::ImageHeight);  // follows the width at the picture's aspect ratio
    QTextCursor cursor(browser_->document());
    cursor.setPosition(p.position);
    cursor.setPosition(p.position + p.length, QTextCursor::KeepAnchor);
    cursor.setCharFormat(p.format);
  }
}

}  // namespace mx::widgets
