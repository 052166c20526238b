#include "e2e_monkey_dialogs.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDialog>
#include <QEvent>
#include <QMessageBox>
#include <QTest>
#include <utility>

namespace mx::e2e {

namespace {
constexpr int kSweepMs = 50;
constexpr int kPopupSweeps = 8;  // a popup the monkey left open closes after about 400 ms

QString describeWindow(const QWidget* w) {
  return QString("%1 '%2'").arg(w->metaObject()->className(), w->windowTitle());
}
}  // namespace

DialogCloser::DialogCloser(Dice& dice, ActionLog& log, std::function<qint64()> elapsed_ms)
    : dice_(dice), log_(log), elapsed_ms_(std::move(elapsed_ms)) {
  qApp->installEventFilter(this);
  sweeper_.setInterval(kSweepMs);
  connect(&sweeper_, &QTimer::timeout, this, &DialogCloser::sweep);
  sweeper_.start();
}

DialogCloser::~DialogCloser() {
  qApp->removeEventFilter(this);
}

bool DialogCloser::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() == QEvent::Show && watched->isWidgetType()) {
    auto* dialog = qobject_cast<QDialog*>(watched);
    if (dialog && dialog->isWindow()) {
      log_.note("dialog shown: " + describeWindow(dialog), elapsed_ms_());
      QTimer::singleShot(0, dialog, [this, dialog] { closeDialog(dialog); });
    }
  }
  return false;
}

void DialogCloser::closeDialog(QWidget* dialog) {
  if (!dialog->isVisible()) return;
  ++dialogs_closed_;
  if (auto* box = qobject_cast<QMessageBox*>(dialog); box && !box->buttons().isEmpty()) {
    const QList<QAbstractButton*> buttons = box->buttons();
    QAbstractButton* button = buttons[dice_.below(int(buttons.size()))];
    log_.note(QString("dialog answered: %1 with '%2'").arg(describeWindow(box), button->text()), elapsed_ms_());
    button->click();
    return;
  }
  log_.note("dialog closed with Escape: " + describeWindow(dialog), elapsed_ms_());
  QTest::keyClick(dialog, Qt::Key_Escape);
  if (dialog->isVisible()) {
    if (auto* d = qobject_cast<QDialog*>(dialog))
      d->reject();
    else
      dialog->close();
  }
}

void DialogCloser::closePopup(QWidget* popup) {
  ++popups_closed_;
  log_.note("popup closed with Escape: " + describeWindow(popup), elapsed_ms_());
  QTest::keyClick(popup, Qt::Key_Escape);
  if (popup->isVisible()) popup->close();
}

void DialogCloser::sweep() {
  if (QWidget* modal = QApplication::activeModalWidget()) closeDialog(modal);
  QWidget* popup = QApplication::activePopupWidget();
  if (!popup || popup != popup_seen_) {
    popup_seen_ = popup;
    popup_sweeps_ = 0;
    return;
  }
  if (++popup_sweeps_ >= kPopupSweeps) {
    closePopup(popup);
    popup_seen_ = nullptr;
  }
}

QStringList DialogCloser::openNow() const {
  QStringList open;
  if (QWidget* modal = QApplication::activeModalWidget()) open << describeWindow(modal);
  if (QWidget* popup = QApplication::activePopupWidget()) open << describeWindow(popup);
  return open;
}

void DialogCloser::closeAll() {
  for (int i = 0; i < 10; ++i) {
    if (QWidget* popup = QApplication::activePopupWidget())
      closePopup(popup);
    else if (QWidget* modal = QApplication::activeModalWidget())
      closeDialog(modal);
    else
      return;
    QCoreApplication::processEvents();
  }
}

}  // namespace mx::e2e
