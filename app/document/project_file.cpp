// Project files on disk: loadProject (read, parse, validate) and saveProject (atomic QSaveFile).
#include <QFileInfo>
#include <QJsonDocument>
#include <algorithm>

#include "core/invalid_input.h"
#include "document/frf_paths.h"
#include "document/input_files.h"
#include "document/json_format.h"
#include "document/output_file.h"
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
  if (!QFileInfo::exists(path)) throw ProjectError(QString("%1: project file not found").arg(path));
  QByteArray data;
  try {
    data = readBoundedFile(path, kProjectFileLimit);
  } catch (const InvalidInput& e) {
    throw ProjectError(QString("%1: %2").arg(path, QString::fromStdString(e.what())));
  }
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
  if (const QString error = writeFileAtomically(path, text); !error.isEmpty())
    throw ProjectError(QString("%1: cannot write project file: %2").arg(path, error));
}

}  // namespace mx::app
