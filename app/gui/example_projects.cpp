#include "example_projects.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>

namespace mx::gui {

namespace {
const QString kSubfolder = QStringLiteral("millexpert/projects");
constexpr qint64 kMaxHeaderRead = 4 * 1024 * 1024;  // examples are a few kB; never read a huge file whole

QStringList examplesIn(const QString& dir) {
  return QDir(dir).entryList({"*.mxproj"}, QDir::Files | QDir::Readable, QDir::Name);
}

widgets::StartEntry describe(const QString& path) {
  widgets::StartEntry entry{path, QFileInfo(path).fileName(), {}};
  QFile file(path);
  if (file.size() > kMaxHeaderRead || !file.open(QIODevice::ReadOnly)) return entry;
  const QJsonObject project = QJsonDocument::fromJson(file.readAll()).object();
  if (const QString name = project.value("name").toString(); !name.isEmpty()) entry.title = name;
  entry.description = project.value("description").toString();
  return entry;
}
}  // namespace

QStringList exampleProjectDirs() {
  return exampleProjectDirs(QCoreApplication::applicationDirPath());
}

QStringList exampleProjectDirs(const QString& executable_dir) {
  QStringList dirs;
  dirs << QDir(executable_dir).absoluteFilePath("../share/" + kSubfolder);
  // An installed copy never reads the source tree it was built from, even on the machine that built it.
  const QString build_dir = QFileInfo(QStringLiteral(MX_BUILD_DIR)).canonicalFilePath();
  const QString from = QFileInfo(executable_dir).canonicalFilePath();
  if (!build_dir.isEmpty() && (from == build_dir || from.startsWith(build_dir + '/')))
    dirs << QFileInfo(QStringLiteral(MX_DEFAULT_PROJECT)).absolutePath();
  for (const QString& data : QStandardPaths::standardLocations(QStandardPaths::GenericDataLocation))
    dirs << QDir(data).absoluteFilePath(kSubfolder);
  for (QString& dir : dirs) dir = QDir::cleanPath(dir);
  dirs.removeDuplicates();
  return dirs;
}

QString exampleProjectsDir() {
  for (const QString& dir : exampleProjectDirs())
    if (!examplesIn(dir).isEmpty()) return dir;
  return {};
}

QVector<widgets::StartEntry> exampleProjects() {
  QVector<widgets::StartEntry> entries;
  const QString dir = exampleProjectsDir();
  if (dir.isEmpty()) return entries;
  for (const QString& name : examplesIn(dir)) entries << describe(QDir(dir).absoluteFilePath(name));
  return entries;
}

QString exampleProject(const QString& file_name) {
  const QString dir = exampleProjectsDir();
  if (dir.isEmpty()) return {};
  const QString path = QDir(dir).absoluteFilePath(file_name);
  return QFileInfo::exists(path) ? path : QString();
}

}  // namespace mx::gui
