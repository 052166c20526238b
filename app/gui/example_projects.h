#pragma once
// The example projects shipped with MillExpert (projects/*.mxproj, docs: README "Layout"). Looked for
// in order: <prefix>/share/millexpert/projects beside the executable's <prefix>/bin (an install,
// wherever it was relocated), the source tree (MX_DEFAULT_PROJECT's folder) only when the executable
// runs from the build folder (MX_BUILD_DIR), then the system's data folders (QStandardPaths, e.g.
// /usr/share/millexpert/projects). The first folder that holds any example is the one used.
#include <QString>
#include <QStringList>
#include <QVector>

#include "start_screen.h"

namespace mx::gui {

QStringList exampleProjectDirs();  // the candidate folders, in the order above
// The same for an executable in executable_dir (exampleProjectDirs() passes the running one's).
QStringList exampleProjectDirs(const QString& executable_dir);
QString exampleProjectsDir();  // the first that holds a .mxproj; "" when none does
// The examples by file name, each with the project's name and description (read from the file; a
// file that is not a JSON object is listed by its file name).
QVector<widgets::StartEntry> exampleProjects();
QString exampleProject(const QString& file_name);  // its absolute path; "" when missing

}  // namespace mx::gui
