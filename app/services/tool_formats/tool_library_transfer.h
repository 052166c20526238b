#pragma once
// Tool libraries as files, for the CLI (library-import, library-export) and the GUI alike: the format
// (named or guessed), the whole-file import, the merge into a project and the export
// (docs/tool-libraries.md).
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "document/project.h"
#include "services/tool_formats/tool_library_io.h"

namespace mx::app {

enum class ToolLibraryFormat { Fusion, FreeCad, LinuxCnc, Csv, Json };

// "fusion", "freecad", "linuxcnc", "csv", "json": the --format values.
QString toolLibraryFormatName(ToolLibraryFormat format);
std::optional<ToolLibraryFormat> toolLibraryFormatFromName(const QString& name);
const QStringList& toolLibraryFormatNames();

// The format of an existing file from its content (a zip, a Fusion, FreeCAD or MillExpert JSON
// document, a LinuxCNC table), then its suffix; throws ToolLibraryError naming the file when neither
// tells.
ToolLibraryFormat guessImportFormat(const QString& path);
// The format of an export from its path: .tools or .json with --format fusion, a folder or .fctl
// (FreeCAD), .tbl (LinuxCNC), .csv, .json or .mxproj (MillExpert JSON).
ToolLibraryFormat guessExportFormat(const QString& path);

// Reads and checks the whole file (all or nothing); a LinuxCNC table and its side file, a FreeCAD
// library and its bits. Throws ToolLibraryError (bad content) or ProjectError (unreadable file).
ImportedLibrary readToolLibrary(const QString& path, ToolLibraryFormat format, const ToolImportOptions& options);
// Only the tools of `ids` (in the file's order); throws naming an id the library does not have.
ImportedLibrary selectTools(const ImportedLibrary& library, const QStringList& ids, const QString& file);

struct RenamedTool {
  QString from;
  QString to;
  bool operator==(const RenamedTool&) const = default;
};

struct LibraryMerge {
  Project project;
  QStringList ids;  // the imported tools' ids in the project, in the file's order
  std::vector<RenamedTool> renamed;
};

// `base` with the tools: replacing its library or appended to it. An id already taken (in the
// project, or earlier in the file) gets the first free suffix "-2", "-3", ... The result is validated
// whole; throws ProjectError ("the imported tools do not fit the project: ...").
LibraryMerge mergeImportedTools(const Project& base, const std::vector<ToolSpec>& tools, bool replace);

// Writes the library atomically, file by file; returns the files written. `path` is a folder for
// FreeCAD (Library/<name>.fctl and Bit/*.fctb inside it). Throws ProjectError on I/O failure.
QStringList writeToolLibrary(const std::vector<ToolSpec>& tools, const QString& path, ToolLibraryFormat format);

}  // namespace mx::app
