// Project files on disk: loadProject (read, parse, validate) and saveProject (atomic QSaveFile).
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QSaveFile>
#include <algorithm>

#include "document/frf_paths.h"
#include "document/json_format.h"
#include "document/project.h"

namespace mx::app {

namespace {

QString parseErrorMessage(const QString& path, const QByteArray& data, const QJsonParseError& error) {
  const qsizetype offset = std::clamp<qsizetype>(error.offset, 0, data.size());
  const QByteArray before = data.left(offset);
  const qsizetype line = before.count('\n') + 1;
  const qsizetype column = offset - (before.lastIndexOf('\n') + 1) + 1;
  return QString("%1: invalid JSON at line %2, column %3 (offset %4): %5")
      .arg(path)
      .arg(line)
      .arg(column)
      .arg(offset)
      .arg(error.errorString());
}

}  // namespace

Project loadProject(const QString& path) {
  QFile file(path);
  if (!file.exists()) throw ProjectError(QString("%1: project file not found").arg(path));
  if (!file.open(QIODevice::ReadOnly))
    throw ProjectError(QString("%1: cannot open project file: %2").arg(path, file.errorString()));
  const QByteArray data = file.readAll();
  QJsonParseError error;
  const QJsonDocument document = QJsonDocument::fromJson(data, &error);
  if (error.error != QJsonParseError::NoError) throw ProjectError(parseErrorMessage(path, data, error));
  if (!document.isObject())
    throw ProjectError(QString("%1: the top level must be a JSON object, got %2")
                           .arg(path, document.isArray() ? "an array" : "nothing"));
  try {
    Project project = projectFromJson(document.object());
    project.folder = QFileInfo(path).absolutePath();
    return project;
  } catch (const ProjectError& e) {
    throw ProjectError(QString("%1: %2").arg(path, QString::fromStdString(e.what())));
  }
}

void saveProject(const Project& project, const QString& path) {
  const QString folder = QFileInfo(path).absolutePath();
  const QByteArray text = formatProjectJson(projectToJson(withFrfPathsRelativeTo(project, folder)));
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly))
    throw ProjectError(QString("%1: cannot write project file: %2").arg(path, file.errorString()));
  if (file.write(text) != text.size()) {
    const QString reason = file.errorString();
    file.cancelWriting();
    throw ProjectError(QString("%1: cannot write project file: %2").arg(path, reason));
  }
  if (!file.commit()) throw ProjectError(QString("%1: cannot save project file: %2").arg(path, file.errorString()));
}

}  // namespace mx::app
