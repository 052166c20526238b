#pragma once
// Test helper: the paths of the example projects and the test fixtures, and their raw contents.
#include <QByteArray>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QTemporaryDir>
#include <QtGlobal>

namespace mx::test {

inline QString projectsPath(const QString& name) {
  return QString(MX_PROJECTS_DIR) + "/" + name;
}
// The bundled examples that several test files read.
inline const QString kRubio = projectsPath("rubio2006-tool-selection.mxproj");  // Aluminium; R1, R2
inline const QString kParetoCase = projectsPath("rubio-pareto-case.mxproj");
inline const QString kSdnrp = projectsPath("cus-zuperl-sdnrp.mxproj");

// Copies every file below `from` into `to`, keeping the folders.
inline void copyTree(const QString& from, const QString& to) {
  QDirIterator it(from, QDir::Files, QDirIterator::Subdirectories);
  while (it.hasNext()) {
    const QString source = it.next();
    const QString target = to + "/" + QDir(from).relativeFilePath(source);
    QDir().mkpath(QFileInfo(target).absolutePath());
    if (!QFile::copy(source, target)) qFatal("cannot copy %s to %s", qPrintable(source), qPrintable(target));
  }
}

// The example `name` in a copy of projects/ (with the tap tests, programs and libraries the examples
// name) made once per test process in its temporary folder: a window that opens it writes its
// autosave there, never into the source tree. Called from test functions (after the runner has set
// TMPDIR), never at static initialisation.
inline QString exampleCopy(const QString& name) {
  static const QTemporaryDir dir;
  static const bool copied = (copyTree(MX_PROJECTS_DIR, dir.path()), true);
  Q_UNUSED(copied);
  return dir.filePath(name);
}

inline QString fixturePath(const QString& name) {
  return QString(MX_TEST_DATA_DIR) + "/projects/" + name;
}

inline QByteArray readBytes(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) qFatal("cannot open %s", qPrintable(path));
  return f.readAll();
}

// Writes `bytes` to `name` in `dir`; returns its path.
inline QString writeText(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes) {
  QString path = dir.filePath(name);
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size()) qFatal("cannot write %s", qPrintable(path));
  return path;
}

inline QJsonObject readJson(const QString& path) {
  return QJsonDocument::fromJson(readBytes(path)).object();
}

}  // namespace mx::test
