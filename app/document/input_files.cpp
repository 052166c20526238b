#include "document/input_files.h"

#include <QFile>

namespace mx::app {

QByteArray readBoundedFile(const QString& path, const InputFileLimit& limit) {
  return QByteArray::fromStdString(readInputFile(QFile::encodeName(path).toStdString(), limit));
}

}  // namespace mx::app
