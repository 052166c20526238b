#include "input_feedback.h"

#include <QAbstractItemView>
#include <QLabel>
#include <QTimer>
#include <algorithm>

namespace mx::widgets {

namespace {

constexpr char kNoteName[] = "inputNote";
constexpr int kMinWidth = 280;  // px: a sentence of a few words per line, even under a narrow cell

QLabel* createNote(QWidget* window) {
  auto* note = new QLabel(window);
  note->setObjectName(kNoteName);
  note->setWordWrap(true);
  note->setStyleSheet("QLabel { color: #a00000; background: #fff4f4; border: 1px solid #c00000; padding: 2px 4px; }");
  // It covers other widgets for a few seconds: clicks go through to them.
  note->setAttribute(Qt::WA_TransparentForMouseEvents);
  auto* timer = new QTimer(note);
  timer->setSingleShot(true);
  timer->setInterval(kInputNoteMs);
  QObject::connect(timer, &QTimer::timeout, note, &QLabel::hide);
  note->hide();
  return note;
}

}  // namespace

QLabel* inputNote(const QWidget* field) {
  return field ? field->window()->findChild<QLabel*>(kNoteName, Qt::FindDirectChildrenOnly) : nullptr;
}

void showInputNote(QWidget* field, const QString& text, const QRect& area) {
  // Nothing for a field not shown; a closing window is hidden first, then its focused box ends its edit.
  if (!field || !field->isVisible() || field->window()->isHidden()) return;
  QWidget* window = field->window();
  QLabel* note = inputNote(field);
  if (!note) note = createNote(window);
  const QRect shown = area.isEmpty() ? field->rect() : area;
  const QRect cell(field->mapTo(window, shown.topLeft()), shown.size());
  const int width = std::min(std::max(cell.width(), kMinWidth), std::max(window->width(), 1));
  note->setText(text);
  const int height = note->heightForWidth(width) > 0 ? note->heightForWidth(width) : note->sizeHint().height();
  const int x = std::clamp(cell.left(), 0, std::max(0, window->width() - width));
  const bool below = cell.bottom() + 1 + height <= window->height() || cell.top() < height;
  note->setGeometry(x, below ? cell.bottom() + 1 : cell.top() - height, width, height);
  note->show();
  note->raise();
  note->findChild<QTimer*>()->start();
}

void showInputNote(QAbstractItemView* view, const QModelIndex& index, const QString& text) {
  if (!view) return;
  const QRect cell = index.isValid() ? view->visualRect(index) : QRect();
  if (cell.isEmpty() || !view->viewport()->rect().intersects(cell)) {
    showInputNote(view, text, QRect(0, 0, view->width(), 1));
    return;
  }
  showInputNote(view->viewport(), text, cell);
}

void hideInputNote(const QWidget* field) {
  if (QLabel* note = inputNote(field)) note->hide();
}

}  // namespace mx::widgets
