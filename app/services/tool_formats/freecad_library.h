#pragma once
// FreeCAD CAM tool bits (.fctb) and tool libraries (.fctl), both JSON (docs/tool-libraries.md,
// "FreeCAD"). A library lists {"nr", "path"} entries; each path names a bit file, which FreeCAD keeps in
// the Bit/ folder beside the Library/ folder. A bit names its shape and gives the shape's parameters
// as FreeCAD quantities ("6.00 mm", "0.25 in"). The bit's whole record stays with the imported tool
// (ToolSpec::origin, format "freecad"), and MillExpert's own data travels in the bit's "attribute"
// object under "MillExpert".
#include <QByteArray>
#include <QString>
#include <functional>
#include <utility>
#include <vector>

#include "services/tool_formats/tool_library_io.h"

namespace mx::app {

// The bit a library entry's "path" names; throws ToolLibraryError when it cannot be found or read.
using FreeCadBitLoader = std::function<QByteArray(const QString& bitReference)>;

// A library: each entry's bit, as tool "T<nr>". Bits of shapes that do not mill are skipped; a bit
// without "Flutes" takes its carried count, else options.teeth, else the import is refused.
ImportedLibrary readFreeCadLibrary(const QByteArray& fctl, const QString& fileName, const FreeCadBitLoader& loadBit,
                                   const ToolImportOptions& options = {});
// One bit, as a tool named by the bit's "name" (else the file's base name); the same teeth rule.
ImportedLibrary readFreeCadBit(const QByteArray& fctb, const QString& fileName, const ToolImportOptions& options = {});

// The files of an export, relative to the export folder: "Library/<libraryName>.fctl" and one
// "Bit/<bit>.fctb" per tool, the layout FreeCAD reads (a library's bits in ../Bit/).
struct FreeCadExport {
  QByteArray library;
  QString libraryName;
  std::vector<std::pair<QString, QByteArray>> bits;  // relative path, content
};
FreeCadExport writeFreeCadLibrary(const std::vector<ToolSpec>& tools, const QString& libraryName);

// Library and bit files on disk -------------------------------------------------------------------

inline constexpr qsizetype kMaxFreeCadLibraryTools = 10000;              // entries of one .fctl
inline constexpr qsizetype kMaxFreeCadBitBytes = 64 * 1024 * 1024;       // all the bits one import reads
inline const QString kFreeCadLibraryFolder = QStringLiteral("Library");  // FreeCAD's Tools/ layout
inline const QString kFreeCadBitFolder = QStringLiteral("Bit");

// A .fctl or a .fctb (by suffix, else by content: a "tools" array), or an export folder holding one
// Library/*.fctl; each file a regular file of at most
// 64 MB (kCamToolLibraryFileLimit). A library's bits are looked up as FreeCAD does (fctl.py): the
// entry's path relative to the library's folder, then in the Bit/ folder beside it.
ImportedLibrary readFreeCadFile(const QString& path, const ToolImportOptions& options = {});
// Writes the export under `folder` (created if missing), each file atomically; returns why a file was
// not written ("Bit/T1.fctb: a directory, not a regular file"), or an empty string.
QString writeFreeCadFolder(const FreeCadExport& files, const QString& folder);

}  // namespace mx::app
