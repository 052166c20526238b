#pragma once
// The LinuxCNC tool table (tool.tbl; LinuxCNC manual, "Tool Table Format"; src/emc/rs274ngc/tool_parse.cc):
// one tool per line, words in any order and any case, "T<tool> P<pocket> X.. Y.. Z.. A.. B.. C.. U.. V..
// W.. D<diameter> I.. J.. Q.. ;comment"; a line that starts with ';' is a remark. Values are in the
// machine's units, which the table does not state: MillExpert reads mm unless a remark line declares
// "units: inch" (or "units: mm"), and writes that remark. The table has no flute count and no free
// field: the count comes from the comment ("3FL", "3 flutes"), else the side file, else --teeth, and
// MillExpert's data travels in the side file (tool_library_io.h, sideFilePath). docs/tool-libraries.md.
#include <QByteArray>
#include <QString>
#include <optional>
#include <vector>

#include "services/tool_formats/tool_library_io.h"

namespace mx::app {

// Every tool line as tool "T<n>" (all-or-nothing: the first bad line throws ToolLibraryError naming the
// file, the line, the tool and the word). `sideFile` is the content of sideFilePath(fileName), if any.
ImportedLibrary readLinuxCncToolTable(const QByteArray& table, const QString& fileName,
                                      const ToolImportOptions& options, const std::optional<QByteArray>& sideFile);

struct LinuxCncExport {
  QByteArray table;
  QByteArray sideFile;  // for sideFilePath(<the table's path>)
};
// A tool imported from a table is written as its line was (pocket, offsets, word order, comment), with
// its number, diameter and flute phrase updated; the table keeps the units of the tables its tools came
// from (mm when they differ, or when no tool came from a table).
LinuxCncExport writeLinuxCncToolTable(const std::vector<ToolSpec>& tools);

}  // namespace mx::app
