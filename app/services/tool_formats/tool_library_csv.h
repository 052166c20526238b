#pragma once
// The tool library as files (Qt Core only, no widgets): CSV (docs/tool-library-csv.md) and JSON (the
// `tools` array of the project format), and the all-or-nothing merge of an imported library into a
// project. Every function reports errors as text ("" = ok) and never changes its inputs halfway.
#include <QByteArray>
#include <QJsonArray>
#include <QString>
#include <QStringList>
#include <vector>

#include "document/project.h"

namespace mx::app {

// A parsed library file: the tools (from JSON with their unknown keys), the source line of each
// tool's first row (CSV; 0 for JSON), and the error ("" = ok).
struct ToolLibraryFile {
  std::vector<ToolSpec> tools;
  std::vector<int> lines;
  int idColumn = 1;  // CSV column of tool_id (1-based), for messages about ids
  QString error;
  bool ok() const { return error.isEmpty(); }
};

class ToolLibraryCsv {
 public:
  // The fixed header row (column order of the export; the import maps columns by header name).
  static const QStringList& columns();

  // One row per mode (x modes first, then y); a tool without modes gets one row with an empty axis.
  static QByteArray toCsv(const std::vector<ToolSpec>& tools);
  // Parses and range-checks everything; the first bad cell is reported as
  // "line 4, column 9 (freq_Hz): '-3' must be > 0". On error `tools` is empty.
  static ToolLibraryFile fromCsv(const QByteArray& text);

  // A minimal project file holding only the tools (loadable as a .mxproj).
  static QByteArray toJson(const std::vector<ToolSpec>& tools);
  // Accepts a project file / library export (object with "tools") or a bare tools array. Errors
  // name the field path, e.g. "tools[0].modes_x[0].damping_pct = 150: must be in (0, 100)".
  static ToolLibraryFile fromJson(const QByteArray& text);

  // `base` with the imported tools (replacing or appended to its library), validated as a whole
  // (validateProject). Returns "" and sets `merged`, or the reason (with the CSV line when known).
  static QString merge(const Project& base, const ToolLibraryFile& file, bool replace, Project& merged);

  // Atomic write of a regular or new file (writeFileAtomically: a device, FIFO or folder is
  // refused); "" = ok.
  static QString writeFile(const QString& path, const QByteArray& bytes);
  // Reads a whole regular file of at most 16 MB (kToolLibraryFileLimit) into `bytes`; "" = ok.
  static QString readFile(const QString& path, QByteArray& bytes);
};

}  // namespace mx::app
