#pragma once
// A view that may not apply to the project: either the view itself or, in its place, a short notice
// of why not ("This project has no Pareto study") and the action that makes it apply ("Add a Pareto
// section"). An empty plot with a 0-1 axis says nothing; the notice says what is missing.
#include <QStackedWidget>
#include <QString>

class QLabel;
class QPushButton;

namespace mx::widgets {

class NoticeStack : public QStackedWidget {
  Q_OBJECT
 public:
  explicit NoticeStack(QWidget* content, QWidget* parent = nullptr);

  // The notice instead of the view; an empty `action` shows no button.
  void showNotice(const QString& message, const QString& action = {});
  void showContent();
  bool noticeShown() const;
  QString noticeText() const;
  QPushButton* actionButton() const { return action_; }

 signals:
  void actionTriggered();

 private:
  QWidget* content_;
  QLabel* message_;
  QPushButton* action_;
};

}  // namespace mx::widgets
