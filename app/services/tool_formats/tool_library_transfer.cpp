#include "services/tool_formats/tool_library_transfer.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>

#include "core/invalid_input.h"
#include "document/input_files.h"
#include "document/output_file.h"
#include "document/project_validation.h"
#include "document/shortened_text.h"
#include "services/tool_formats/freecad_library.h"
#include "services/tool_formats/fusion_library.h"
#include "services/tool_formats/linuxcnc_tool_table.h"
#include "services/tool_formats/tool_library_csv.h"

namespace mx::app {

namespace {

struct FormatName {
  ToolLibraryFormat format;
  const char* name;
};
constexpr FormatName kFormatNames[] = {{ToolLibraryFormat::Fusion, "fusion"},
                                       {ToolLibraryFormat::FreeCad, "freecad"},
                                       {ToolLibraryFormat::LinuxCnc, "linuxcnc"},
                                       {ToolLibraryFormat::Csv, "csv"},
                                       {ToolLibraryFormat::Json, "json"}};

QByteArray readLibraryFile(const QString& path, const InputFileLimit& limit) {
  try {
    return readBoundedFile(path, limit);
  } catch (const InvalidInput& e) {
    throw ToolLibraryError(QString("%1: %2").arg(quoted(path), QString::fromStdString(e.what())));
  }
}

// The format a JSON document's shape names: a Fusion library ({"data": [tools with "geometry"]}), a
// FreeCAD library ({"tools": [{"nr", "path"}]}) or bit ({"shape", "parameter"}), or a MillExpert
// project or library.
std::optional<ToolLibraryFormat> jsonFormat(const QByteArray& bytes) {
  const QJsonDocument doc = QJsonDocument::fromJson(bytes);
  if (doc.isArray()) return ToolLibraryFormat::Json;
  if (!doc.isObject()) return std::nullopt;
  const QJsonObject root = doc.object();
  if (root.value("data").isArray()) return ToolLibraryFormat::Fusion;
  if (root.contains("shape") && root.contains("parameter")) return ToolLibraryFormat::FreeCad;
  const QJsonValue first = root.value("tools").toArray().first();
  if (first.toObject().contains("path") && first.toObject().contains("nr")) return ToolLibraryFormat::FreeCad;
  if (root.value("format").toString() == "millexpert-project" || root.value("tools").isArray())
    return ToolLibraryFormat::Json;
  return std::nullopt;
}

std::optional<ToolLibraryFormat> formatFromSuffix(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix == "tools") return ToolLibraryFormat::Fusion;
  if (suffix == "fctl" || suffix == "fctb") return ToolLibraryFormat::FreeCad;
  if (suffix == "tbl") return ToolLibraryFormat::LinuxCnc;
  if (suffix == "csv") return ToolLibraryFormat::Csv;
  if (suffix == "json" || suffix == "mxproj") return ToolLibraryFormat::Json;
  return std::nullopt;
}

ImportedLibrary fromCsvOrJson(const QString& path, bool csv) {
  const QByteArray bytes = readLibraryFile(path, kToolLibraryFileLimit);
  ToolLibraryFile file = csv ? ToolLibraryCsv::fromCsv(bytes) : ToolLibraryCsv::fromJson(bytes);
  if (!file.ok()) throw ToolLibraryError(QString("%1: %2").arg(QFileInfo(path).fileName(), file.error));
  return {std::move(file.tools), {}};
}

ImportedLibrary fromLinuxCnc(const QString& path, const ToolImportOptions& options) {
  const QByteArray table = readLibraryFile(path, kCamToolLibraryFileLimit);
  const QString side = sideFilePath(path);
  std::optional<QByteArray> sideFile;
  if (QFileInfo::exists(side)) sideFile = readLibraryFile(side, kCamToolLibraryFileLimit);
  return readLinuxCncToolTable(table, QFileInfo(path).fileName(), options, sideFile);
}

QString uniqueId(const QString& id, const QSet<QString>& taken) {
  if (!taken.contains(id)) return id;
  for (int n = 2;; ++n) {
    QString candidate = QString("%1-%2").arg(id).arg(n);
    if (!taken.contains(candidate)) return candidate;
  }
}

void writeOrThrow(const QString& path, const QByteArray& bytes, QStringList& written) {
  const QString problem = writeFileAtomically(path, bytes);
  if (!problem.isEmpty()) throw ProjectError(QString("%1: %2").arg(quoted(path), problem));
  written << path;
}

}  // namespace

QString toolLibraryFormatName(ToolLibraryFormat format) {
  for (const FormatName& f : kFormatNames)
    if (f.format == format) return QString::fromLatin1(f.name);
  return {};
}

std::optional<ToolLibraryFormat> toolLibraryFormatFromName(const QString& name) {
  for (const FormatName& f : kFormatNames)
    if (name == QLatin1String(f.name)) return f.format;
  return std::nullopt;
}

const QStringList& toolLibraryFormatNames() {
  static const QStringList names = [] {
    QStringList n;
    for (const FormatName& f : kFormatNames) n << QString::fromLatin1(f.name);
    return n;
  }();
  return names;
}

ToolLibraryFormat guessImportFormat(const QString& path) {
  if (QFileInfo(path).isDir()) return ToolLibraryFormat::FreeCad;  // an exported Library/ + Bit/ folder
  const QByteArray bytes = readLibraryFile(path, kCamToolLibraryFileLimit);
  if (bytes.startsWith("PK\x03\x04")) return ToolLibraryFormat::Fusion;
  if (const std::optional<ToolLibraryFormat> json = jsonFormat(bytes)) return *json;
  if (const std::optional<ToolLibraryFormat> suffix = formatFromSuffix(path)) return *suffix;
  throw ToolLibraryError(QString("%1: cannot tell the library's format from its content or name; give --format "
                                 "(one of %2)")
                             .arg(QFileInfo(path).fileName(), toolLibraryFormatNames().join(", ")));
}

ToolLibraryFormat guessExportFormat(const QString& path) {
  if (QFileInfo(path).isDir()) return ToolLibraryFormat::FreeCad;
  if (const std::optional<ToolLibraryFormat> suffix = formatFromSuffix(path)) return *suffix;
  throw ToolLibraryError(QString("%1: cannot tell the format from the name (.tools, .fctl or a folder, .tbl, .csv, "
                                 ".json); give --format (one of %2)")
                             .arg(quoted(path), toolLibraryFormatNames().join(", ")));
}

ImportedLibrary readToolLibrary(const QString& path, ToolLibraryFormat format, const ToolImportOptions& options) {
  switch (format) {
    case ToolLibraryFormat::Fusion:
      return readFusionLibrary(readLibraryFile(path, kCamToolLibraryFileLimit), QFileInfo(path).fileName());
    case ToolLibraryFormat::FreeCad:
      return readFreeCadFile(path, options);
    case ToolLibraryFormat::LinuxCnc:
      return fromLinuxCnc(path, options);
    case ToolLibraryFormat::Csv:
      return fromCsvOrJson(path, true);
    case ToolLibraryFormat::Json:
      return fromCsvOrJson(path, false);
  }
  throw ToolLibraryError("unknown tool library format");
}

ImportedLibrary selectTools(const ImportedLibrary& library, const QStringList& ids, const QString& file) {
  QSet<QString> wanted(ids.begin(), ids.end());
  ImportedLibrary selected{{}, library.skipped};
  for (const ToolSpec& tool : library.tools) {
    if (wanted.remove(tool.id)) selected.tools.push_back(tool);
  }
  for (const QString& id : ids) {
    if (wanted.contains(id))
      throw ToolLibraryError(toolLibraryError(file, id, "--tools", "the library has no tool of that id"));
  }
  return selected;
}

LibraryMerge mergeImportedTools(const Project& base, const std::vector<ToolSpec>& tools, bool replace) {
  LibraryMerge merge{base, {}, {}};
  if (replace) merge.project.tools.clear();
  QSet<QString> taken;
  for (const ToolSpec& tool : merge.project.tools) taken.insert(tool.id);
  for (ToolSpec tool : tools) {
    const QString id = uniqueId(tool.id, taken);
    if (id != tool.id) merge.renamed.push_back({tool.id, id});
    tool.id = id;
    taken.insert(id);
    merge.ids << id;
    merge.project.tools.push_back(std::move(tool));
  }
  const QString error = projectValidationError(merge.project);
  if (!error.isEmpty()) throw ProjectError("the imported tools do not fit the project: " + error);
  return merge;
}

QStringList writeToolLibrary(const std::vector<ToolSpec>& tools, const QString& path, ToolLibraryFormat format) {
  QStringList written;
  switch (format) {
    case ToolLibraryFormat::Fusion: {
      const bool zipped = QFileInfo(path).suffix().compare("tools", Qt::CaseInsensitive) == 0;
      writeOrThrow(path, writeFusionLibrary(tools, zipped ? FusionContainer::Zipped : FusionContainer::Json), written);
      break;
    }
    case ToolLibraryFormat::FreeCad: {
      const FreeCadExport files = writeFreeCadLibrary(tools, QFileInfo(path).completeBaseName());
      const QString problem = writeFreeCadFolder(files, path);
      if (!problem.isEmpty()) throw ProjectError(problem);
      written << QDir(path).filePath(kFreeCadLibraryFolder + '/' + files.libraryName + ".fctl");
      for (const auto& bit : files.bits) written << QDir(path).filePath(bit.first);
      break;
    }
    case ToolLibraryFormat::LinuxCnc: {
      const LinuxCncExport files = writeLinuxCncToolTable(tools);
      writeOrThrow(path, files.table, written);
      writeOrThrow(sideFilePath(path), files.sideFile, written);
      break;
    }
    case ToolLibraryFormat::Csv:
      writeOrThrow(path, ToolLibraryCsv::toCsv(tools), written);
      break;
    case ToolLibraryFormat::Json:
      writeOrThrow(path, ToolLibraryCsv::toJson(tools), written);
      break;
  }
  return written;
}

}  // namespace mx::app
