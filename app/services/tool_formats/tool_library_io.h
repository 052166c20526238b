#pragma once
// What every CAM tool-library format shares (docs/tool-libraries.md): the result of an import, its
// errors (naming the file, the tool and the field), and the MillExpert data that travels with a tool
// through a format that cannot hold it, in the format's free field or in a side file.
#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <map>
#include <optional>
#include <vector>

#include "document/project.h"

namespace mx::app {

// A tool of the file that is not a milling cutter (drill, tap, probe, holder): left out, with the reason.
struct SkippedTool {
  QString name;
  QString reason;
  bool operator==(const SkippedTool&) const = default;
};

struct ImportedLibrary {
  std::vector<ToolSpec> tools;
  std::vector<SkippedTool> skipped;
};

struct ToolImportOptions {
  std::optional<int> teeth;  // flute count for tools whose format does not give one (--teeth N)
};

// A bad library file (exit code 2, as every ProjectError).
class ToolLibraryError : public ProjectError {
 public:
  using ProjectError::ProjectError;
};

// "tools.json: tool 'T7', geometry.DC: '-3' must be > 0"; an empty tool or field is left out.
QString toolLibraryError(const QString& file, const QString& tool, const QString& field, const QString& what);

// The MillExpert keys of a tool that no CAM format holds: modes, tap-test FRFs, cutting coefficients,
// pitch, runout, force limit, radial depth and helix.
QJsonObject dynamicsPayload(const ToolSpec& tool);
// `mapped` (what the format gave) with the payload's keys: the payload's modes, FRFs, coefficients,
// pitch, runout, force limit and radial depth; its helix only when the format gave none (0). The
// result is validated as a project tool; a bad value throws ToolLibraryError naming `file`, the tool
// and the field.
ToolSpec withPayload(const ToolSpec& mapped, const QJsonObject& payload, const QString& file);
// The project rules for one tool, as a ToolLibraryError naming `file` and the tool.
void validateImportedTool(const ToolSpec& tool, const QString& file);

// The side file of a library whose format has no free field: "<folder>/<base name>.millexpert.json".
QString sideFilePath(const QString& libraryPath);
// {"format": "millexpert-tool-dynamics", "version": 1, "tools": [{"id": ..., payload keys}]}.
QByteArray writeSideFile(const std::vector<ToolSpec>& tools);
// Tool id -> payload; throws ToolLibraryError naming `fileName` on a syntax error, a wrong format,
// an entry without an id or a repeated id.
std::map<QString, QJsonObject> readSideFile(const QByteArray& bytes, const QString& fileName);

}  // namespace mx::app
