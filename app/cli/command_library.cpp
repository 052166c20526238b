// millexpert-cli library-import FILE --into PROJECT [--format fusion|freecad|linuxcnc|csv|json] [--teeth N]
//                                [--tools ID,ID,...]
//   {"imported": N, "tools": [ids], "renamed": [{"from", "to"}], "skipped": [{"name", "reason"}]}
// Appends the library's milling tools to the project (saved atomically); an id the project already
// has gets the first free suffix "-2", "-3", ... All or nothing: a bad tool exits 2 naming the file,
// the tool and the field, and the project is left as it was.
// millexpert-cli library-export PROJECT --out FILE [--format fusion|freecad|linuxcnc|csv|json]
//   {"exported": N, "format", "files": [paths]}
// FreeCAD: --out is a folder that receives Library/<name>.fctl and Bit/<tool>.fctb. The format is
// guessed from the file (import) or the name (export) when not given (docs/tool-libraries.md).
#include <QFileInfo>
#include <QJsonArray>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "cli/output_paths.h"
#include "document/project.h"
#include "document/shortened_text.h"
#include "services/tool_formats/tool_library_transfer.h"

namespace mx::app {

namespace {

std::optional<ToolLibraryFormat> formatOption(const QCommandLineParser& parser) {
  if (!parser.isSet("format")) return std::nullopt;
  const QString name = parser.value("format");
  const std::optional<ToolLibraryFormat> format = toolLibraryFormatFromName(name);
  if (!format)
    throw CliError(
        QString("--format = %1: must be one of %2").arg(quoted(name, u'"'), toolLibraryFormatNames().join(", ")),
        kExitBadInput);
  return format;
}

QStringList toolIdsOption(const QCommandLineParser& parser) {
  if (!parser.isSet("tools")) return {};
  QStringList ids;
  for (const QString& id : parser.value("tools").split(u',')) {
    if (id.trimmed().isEmpty())
      throw CliError(QString("--tools = %1: must be tool ids separated by commas, none empty")
                         .arg(quoted(parser.value("tools"), u'"')),
                     kExitBadInput);
    ids << id.trimmed();
  }
  return ids;
}

QJsonObject importJson(const LibraryMerge& merge, const ImportedLibrary& library) {
  QJsonArray renamed;
  for (const RenamedTool& r : merge.renamed) renamed.append(QJsonObject{{"from", r.from}, {"to", r.to}});
  QJsonArray skipped;
  for (const SkippedTool& s : library.skipped) skipped.append(QJsonObject{{"name", s.name}, {"reason", s.reason}});
  return {{"imported", static_cast<qint64>(merge.ids.size())},
          {"tools", QJsonArray::fromStringList(merge.ids)},
          {"renamed", renamed},
          {"skipped", skipped}};
}

}  // namespace

int runLibraryImportCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Append the milling tools of a CAM or controller tool library to a project (docs/tool-libraries.md).");
  parser.addHelpOption();
  parser.addOptions({
      {"into", "The .mxproj project that receives the tools (saved atomically).", "PROJECT"},
      {"format", "fusion, freecad, linuxcnc, csv or json (default: guessed from the file).", "FORMAT"},
      {"teeth", "Flute count of the tools whose library gives none (LinuxCNC, FreeCAD), 1-100.", "N"},
      {"tools", "Import only these tool ids, separated by commas (the ids the library gives them).", "IDS"},
  });
  const QString file = parseSubcommand(parser, arguments, "FILE",
                                       "The tool library: Fusion 360 .json/.tools, FreeCAD .fctl/.fctb, LinuxCNC "
                                       "tool.tbl, MillExpert CSV or JSON.");
  const QString projectPath = requiredOption(parser, "into");
  const std::optional<ToolLibraryFormat> named = formatOption(parser);
  ToolImportOptions options;
  options.teeth = integerOption(parser, "teeth", 1, 100);
  const QStringList ids = toolIdsOption(parser);
  const Project project = loadProject(projectPath);
  const ToolLibraryFormat format = named ? *named : guessImportFormat(file);
  ImportedLibrary library = readToolLibrary(file, format, options);
  if (parser.isSet("tools")) library = selectTools(library, ids, file);
  const LibraryMerge merge = mergeImportedTools(project, library.tools, false);
  saveProject(merge.project, projectPath);
  printJson(importJson(merge, library));
  return kExitOk;
}

int runLibraryExportCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Write a project's tools as a CAM or controller tool library "
      "(docs/tool-libraries.md).");
  parser.addHelpOption();
  parser.addOptions({
      {"out", "The library file to write (FreeCAD: a folder for Library/*.fctl and Bit/*.fctb).", "FILE"},
      {"format", "fusion (.json, or zipped .tools), freecad, linuxcnc, csv or json (default: from --out).", "FORMAT"},
  });
  const QString projectPath = parseSubcommand(parser, arguments);
  const QString out = requiredOption(parser, "out");
  const std::optional<ToolLibraryFormat> named = formatOption(parser);
  const ToolLibraryFormat format = named ? *named : guessExportFormat(out);
  OutputPaths paths;
  if (format != ToolLibraryFormat::FreeCad) paths.output("--out", out);
  const Project project = paths.loadProject(projectPath);
  if (format == ToolLibraryFormat::FreeCad && QFileInfo(out).exists() && !QFileInfo(out).isDir())
    throw CliError(
        QString("--out = %1: FreeCAD libraries are written into a folder, and this is a file").arg(quoted(out, u'"')),
        kExitBadInput);
  const QStringList files = writeToolLibrary(project.tools, out, format);
  printJson({{"exported", static_cast<qint64>(project.tools.size())},
             {"format", toolLibraryFormatName(format)},
             {"files", QJsonArray::fromStringList(files)}});
  return kExitOk;
}

}  // namespace mx::app
