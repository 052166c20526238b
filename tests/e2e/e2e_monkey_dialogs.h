#pragma once
// The dialogs and popups that the monkey's input opens. A dialog is closed as soon as it shows: a
// QMessageBox by one of its buttons at random (accepted or rejected), any other dialog with Escape, a
// file dialog unanswered. A popup menu left open is closed with Escape after a while. This runs in the
// dialog's own event loop, so the driver, waiting below it, goes on once it is closed.
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>
#include <functional>

#include "e2e_monkey_dice.h"
#include "e2e_monkey_log.h"

class QWidget;

namespace mx::e2e {

class DialogCloser : public QObject {
 public:
  DialogCloser(Dice& dice, ActionLog& log, std::function<qint64()> elapsed_ms);
  ~DialogCloser() override;
  DialogCloser(const DialogCloser&) = delete;
  DialogCloser& operator=(const DialogCloser&) = delete;

  int dialogsClosed() const { return dialogs_closed_; }
  int popupsClosed() const { return popups_closed_; }
  // The modal dialogs and popups open now, by class and title (none once the monkey has stopped).
  QStringList openNow() const;
  void closeAll();  // what is open now, at once

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void closeDialog(QWidget* dialog);
  void closePopup(QWidget* popup);
  void sweep();
  Dice& dice_;
  ActionLog& log_;
  std::function<qint64()> elapsed_ms_;
  QTimer sweeper_;
  QPointer<QWidget> popup_seen_;
  int popup_sweeps_ = 0, dialogs_closed_ = 0, popups_closed_ = 0;
};

}  // namespace mx::e2e
