#include "learning_database_dialog.h"

#include <QButtonGroup>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace mx::widgets {

namespace {

const QString kUrlForm = QStringLiteral("postgresql://user@host:5432/learning");

bool isServerUrl(const QString& text) {
  return text.startsWith("postgresql://", Qt::CaseInsensitive) || text.startsWith("postgres://", Qt::CaseInsensitive);
}

}  // namespace

LearningDatabaseDialog::LearningDatabaseDialog(const QString& default_file, Validator validate, QWidget* parent)
    : QDialog(parent),
      default_file_(default_file),
      validate_(std::move(validate)),
      file_choice_(new QRadioButton(tr("SQLite file (one computer)"), this)),
      server_choice_(new QRadioButton(tr("PostgreSQL server (shared by the shop)"), this)),
      file_(new QLineEdit(this)),
      url_(new QLineEdit(this)),
      browse_(new QPushButton(tr("Browse..."), this)),
      test_(new QPushButton(tr("Test connection"), this)),
      ok_(nullptr),
      problem_(new QLabel(this)),
      result_(new QLabel(this)) {
  setWindowTitle(tr("Learning database"));
  setObjectName("learningDatabaseDialog");
  file_choice_->setObjectName("learning_sqlite");
  server_choice_->setObjectName("learning_postgresql");
  file_->setObjectName("learning_file");
  url_->setObjectName("learning_url");
  browse_->setObjectName("learning_browse");
  test_->setObjectName("learning_test");
  problem_->setObjectName("learning_problem");
  result_->setObjectName("learning_result");

  file_choice_->setToolTip(tr("Rule 14 points in one SQLite file on this computer (zero set-up)."));
  server_choice_->setToolTip(tr("Rule 14 points on a PostgreSQL server that every machine and planner shares."));
  file_->setPlaceholderText(tr("Default: %1").arg(default_file_));
  file_->setToolTip(tr("Path of the SQLite file; empty: the default file %1").arg(default_file_));
  url_->setPlaceholderText(kUrlForm);
  url_->setToolTip(
      tr("postgresql://[user@]host[:port]/database[?sslmode=..&connect_timeout=s]; the port defaults to 5432."));
  browse_->setToolTip(tr("Choose or name the SQLite file"));
  test_->setToolTip(tr("Open the database, read its schema version and count its records"));
  for (QLabel* label : {problem_, result_}) {
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  }
  problem_->setStyleSheet("color: #b00020");
  auto* choices = new QButtonGroup(this);
  choices->addButton(file_choice_);
  choices->addButton(server_choice_);
  file_choice_->setChecked(true);

  auto* password =
      new QLabel(tr("The password is never stored: PostgreSQL reads it from the environment variable PGPASSWORD or "
                    "from ~/.pgpass."),
                 this);
  password->setObjectName("learning_password_note");
  password->setWordWrap(true);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  ok_ = buttons->button(QDialogButtonBox::Ok);
  auto* test_row = new QHBoxLayout;
  test_row->addWidget(test_);
  test_row->addWidget(result_, 1);

  auto* form = new QGridLayout;
  form->addWidget(file_choice_, 0, 0, 1, 2);
  form->addWidget(new QLabel(tr("File"), this), 1, 0);
  form->addWidget(buildFileRow(), 1, 1);
  form->addWidget(server_choice_, 2, 0, 1, 2);
  form->addWidget(new QLabel(tr("URL"), this), 3, 0);
  form->addWidget(url_, 3, 1);
  form->addWidget(password, 4, 1);
  form->setColumnStretch(1, 1);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(problem_);
  layout->addLayout(test_row);
  layout->addStretch(1);
  layout->addWidget(buttons);
  setMinimumWidth(640);

  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(browse_, &QPushButton::clicked, this, &LearningDatabaseDialog::browse);
  connect(test_, &QPushButton::clicked, this, &LearningDatabaseDialog::requestTest);
  for (QLineEdit* edit : {file_, url_}) connect(edit, &QLineEdit::textChanged, this, [this] { revalidate(); });
  connect(file_choice_, &QRadioButton::toggled, this, [this] { revalidate(); });
  revalidate();
}

QWidget* LearningDatabaseDialog::buildFileRow() {
  auto* row = new QWidget(this);
  auto* layout = new QHBoxLayout(row);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(file_, 1);
  layout->addWidget(browse_);
  return row;
}

void LearningDatabaseDialog::setLocation(const QString& location) {
  const QString text = location.trimmed();
  const bool server = isServerUrl(text);
  (server ? server_choice_ : file_choice_)->setChecked(true);
  (server ? url_ : file_)->setText(text == default_file_ ? QString() : text);
  revalidate();
}

QString LearningDatabaseDialog::location() const {
  if (usesServer()) return url_->text().trimmed();
  const QString file = file_->text().trimmed();
  return file.isEmpty() ? default_file_ : file;
}

bool LearningDatabaseDialog::usesServer() const {
  return server_choice_->isChecked();
}

QString LearningDatabaseDialog::problem() const {
  return problem_->text();
}

// The dialog's own rules (which field takes which form); the location's rules come from the host.
QString LearningDatabaseDialog::checkUrl(const QString& text) const {
  if (text.isEmpty()) return tr("PostgreSQL URL: empty; enter %1").arg(kUrlForm);
  if (!isServerUrl(text)) return tr("PostgreSQL URL '%1': must start with postgresql:// (%2)").arg(text, kUrlForm);
  const QString why = validate_ ? validate_(text) : QString();
  return why.isEmpty() ? QString() : tr("PostgreSQL URL: %1").arg(why);
}

void LearningDatabaseDialog::revalidate() {
  file_->setEnabled(!usesServer());
  browse_->setEnabled(!usesServer());
  url_->setEnabled(usesServer());
  QString why;
  if (usesServer()) {
    why = checkUrl(url_->text().trimmed());
  } else if (isServerUrl(file_->text().trimmed())) {
    why = tr("SQLite file '%1': this is a server URL; choose \"PostgreSQL server\"").arg(file_->text().trimmed());
  } else if (validate_) {
    const QString problem = validate_(location());
    if (!problem.isEmpty()) why = tr("SQLite file: %1").arg(problem);
  }
  problem_->setText(why);
  problem_->setVisible(!why.isEmpty());
  ok_->setEnabled(why.isEmpty());
  if (test_->text() == tr("Test connection")) test_->setEnabled(why.isEmpty());
  result_->clear();  // a result is of the location it was tested with
}

void LearningDatabaseDialog::browse() {
  const QString start = file_->text().trimmed().isEmpty() ? default_file_ : file_->text().trimmed();
  const QString path =
      QFileDialog::getSaveFileName(this, tr("SQLite learning database"), start, tr("SQLite files (*.sqlite *.db)"),
                                   nullptr, QFileDialog::DontConfirmOverwrite);
  if (!path.isEmpty()) file_->setText(QFileInfo(path).absoluteFilePath());
}

void LearningDatabaseDialog::requestTest() {
  if (!problem().isEmpty()) return;
  test_->setEnabled(false);
  test_->setText(tr("Testing..."));
  result_->setStyleSheet(QString());
  result_->setText(tr("Connecting to %1 ...").arg(location()));
  emit testRequested(location());
}

void LearningDatabaseDialog::showTestResult(bool ok, const QString& text) {
  test_->setText(tr("Test connection"));
  test_->setEnabled(problem().isEmpty());
  result_->setStyleSheet(ok ? "color: #1b5e20" : "color: #b00020");
  result_->setText(text);
}

}  // namespace mx::widgets
