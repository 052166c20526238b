#include "notice_stack.h"

#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace mx::widgets {

NoticeStack::NoticeStack(QWidget* content, QWidget* parent)
    : QStackedWidget(parent), content_(content), message_(new QLabel), action_(new QPushButton) {
  auto* notice = new QWidget;
  notice->setObjectName("notice");
  auto* layout = new QVBoxLayout(notice);
  layout->addStretch(1);
  message_->setObjectName("noticeMessage");
  message_->setWordWrap(true);
  message_->setAlignment(Qt::AlignCenter);
  QFont f = message_->font();
  f.setPointSizeF(f.pointSizeF() * 1.15);
  message_->setFont(f);
  layout->addWidget(message_);
  action_->setObjectName("noticeAction");
  layout->addWidget(action_, 0, Qt::AlignHCenter);
  layout->addStretch(1);
  addWidget(content_);
  addWidget(notice);
  connect(action_, &QPushButton::clicked, this, &NoticeStack::actionTriggered);
}

void NoticeStack::showNotice(const QString& message, const QString& action) {
  message_->setText(message);
  action_->setText(action);
  action_->setVisible(!action.isEmpty());
  setCurrentIndex(1);
}

void NoticeStack::showContent() {
  setCurrentWidget(content_);
}

bool NoticeStack::noticeShown() const {
  return currentIndex() == 1;
}

QString NoticeStack::noticeText() const {
  return noticeShown() ? message_->text() : QString();
}

}  // namespace mx::widgets
