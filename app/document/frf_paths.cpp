#include "document/frf_paths.h"

#include <QDir>
#include <QFileInfo>

namespace mx::app {

namespace {

template <typename Rewrite>
Project withEveryFrfRef(Project project, const Rewrite& rewrite) {
  for (ToolSpec& tool : project.tools) {
    if (tool.frf_x) rewrite(*tool.frf_x);
    if (tool.frf_y) rewrite(*tool.frf_y);
  }
  return project;
}

}  // namespace

QString resolvedFrfPath(const Project& project, const FrfRefSpec& ref) {
  if (QFileInfo(ref.file).isAbsolute()) return QDir::cleanPath(ref.file);
  const QDir base(project.folder.isEmpty() ? QDir::currentPath() : project.folder);
  return QDir::cleanPath(base.absoluteFilePath(ref.file));
}

Project withFrfPathsRelativeTo(const Project& project, const QString& folder) {
  const QDir target(QFileInfo(folder).absoluteFilePath());
  Project out = withEveryFrfRef(project, [&](FrfRefSpec& ref) {
    if (QFileInfo(ref.file).isRelative()) ref.file = target.relativeFilePath(resolvedFrfPath(project, ref));
  });
  out.folder = target.absolutePath();
  return out;
}

Project withAbsoluteFrfPaths(const Project& project) {
  return withEveryFrfRef(project, [&](FrfRefSpec& ref) { ref.file = resolvedFrfPath(project, ref); });
}

}  // namespace mx::app
