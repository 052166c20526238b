#pragma once
// Test helper: the paths of the example projects and the test fixtures, and their raw contents.
#include <QByteArray>
#include <QFile>
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
