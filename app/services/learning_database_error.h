#pragma once
// The one error type of the Rule 14 learning database. Every message names the database file:
// "learning database '/path/learning.sqlite': file is not a database".
#include <QString>
#include <stdexcept>

namespace mx::app {

class LearningDatabaseError : public std::runtime_error {
 public:
  LearningDatabaseError(const QString& file, const QString& what)
      : std::runtime_error(QString("learning database '%1': %2").arg(file, what).toStdString()), file_(file) {}
  const QString& file() const { return file_; }

 private:
  QString file_;
};

}  // namespace mx::app
