#pragma once
// Settings > Learning database: where the Rule 14 learning database lives, an SQLite file (the
// default) or a shared PostgreSQL server given by a URL. The dialog only edits the text: the host
// validates it (a Validator, since the location rules live in the services layer), runs the
// connection test off the GUI thread when testRequested() arrives and answers with showTestResult(),
// and stores the choice when the dialog is accepted.
//
// OK is disabled while the chosen field is invalid; the message under the fields names the field,
// the value and the allowed form. A password never goes into the URL: libpq reads PGPASSWORD or
// ~/.pgpass.
#include <QDialog>
#include <QString>
#include <functional>

class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;

namespace mx::widgets {

class LearningDatabaseDialog : public QDialog {
  Q_OBJECT
 public:
  // The problem with a location (file path or URL), "" when it is valid.
  using Validator = std::function<QString(const QString& location)>;

  LearningDatabaseDialog(const QString& default_file, Validator validate, QWidget* parent = nullptr);

  // A postgresql:// or postgres:// URL selects the server, anything else the file; "" the default file.
  void setLocation(const QString& location);
  // The chosen location: the URL, or the file path (the default file when the field is empty).
  QString location() const;
  bool usesServer() const;
  QString problem() const;  // "" when OK is enabled

  // The host's answer to the last testRequested(): re-enables the Test button.
  void showTestResult(bool ok, const QString& text);

  QRadioButton* fileChoice() const { return file_choice_; }
  QRadioButton* serverChoice() const { return server_choice_; }
  QLineEdit* fileEdit() const { return file_; }
  QLineEdit* urlEdit() const { return url_; }
  QPushButton* browseButton() const { return browse_; }
  QPushButton* testButton() const { return test_; }
  QPushButton* okButton() const { return ok_; }
  QLabel* problemLabel() const { return problem_; }
  QLabel* resultLabel() const { return result_; }

 signals:
  void testRequested(const QString& location);

 private:
  QWidget* buildFileRow();
  void browse();
  void requestTest();
  void revalidate();
  QString checkUrl(const QString& text) const;

  QString default_file_;
  Validator validate_;
  QRadioButton* file_choice_;
  QRadioButton* server_choice_;
  QLineEdit* file_;
  QLineEdit* url_;
  QPushButton* browse_;
  QPushButton* test_;
  QPushButton* ok_;
  QLabel* problem_;
  QLabel* result_;
};

}  // namespace mx::widgets
