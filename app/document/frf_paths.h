#pragma once
// The tools' FRF file paths (frf_x, frf_y): relative to the project file's folder in the file,
// absolute in every snapshot that leaves the document (the engine thread, reports).
#include <QString>

#include "document/project.h"

namespace mx::app {

// The absolute path of `ref.file`: as it is when absolute, else inside project.folder (the working
// directory when the project has no folder).
QString resolvedFrfPath(const Project& project, const FrfRefSpec& ref);

// The project as saved in `folder`: relative FRF paths rewritten to point at the same files from
// there, absolute ones kept; folder set to `folder`.
Project withFrfPathsRelativeTo(const Project& project, const QString& folder);

// The project with every FRF path absolute (resolvedFrfPath).
Project withAbsoluteFrfPaths(const Project& project);

}  // namespace mx::app
