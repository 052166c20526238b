#pragma once
// Test helper: a text file's lines (UTF-8, split at '\n'; empty when it cannot be read).
#include <QFile>
#include <QString>
#include <QStringList>

namespace mx::test {

inline QStringList fileLines(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  return QString::fromUtf8(f.readAll()).split('\n');
}

}  // namespace mx::test
