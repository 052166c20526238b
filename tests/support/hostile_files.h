#pragma once
// Test helper: files a reader must refuse before it reads them, made inside a test's QTemporaryDir:
// a FIFO (reading one would block), a folder, and a sparse file of a given size (no disk blocks used).
#include <sys/stat.h>

#include <QDir>
#include <QFile>
#include <QString>
#include <QTemporaryDir>

namespace mx::test {

inline constexpr qint64 kMB = 1024 * 1024;

// The path of a new input of `kind` in `dir`: "fifo", "folder", "/dev/zero" (itself), or "bytes:N"
// (a sparse file of N bytes). Empty when it cannot be made.
inline QString hostileInput(const QTemporaryDir& dir, const QString& kind) {
  if (kind.startsWith('/')) return kind;
  const QString path = dir.filePath("input-" + QString(kind).replace(':', '-'));
  if (kind == "fifo") return ::mkfifo(QFile::encodeName(path).constData(), 0600) == 0 ? path : QString();
  if (kind == "folder") return QDir(dir.path()).mkdir(QFileInfo(path).fileName()) ? path : QString();
  if (kind.startsWith("bytes:")) {
    QFile file(path);
    const bool made = file.open(QIODevice::WriteOnly) && file.resize(kind.mid(6).toLongLong());
    return made ? path : QString();
  }
  return {};
}

}  // namespace mx::test
