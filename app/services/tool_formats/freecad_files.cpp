#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <memory>

#include "core/invalid_input.h"
#include "document/input_files.h"
#include "document/output_file.h"
#include "document/shortened_text.h"
#include "services/tool_formats/freecad_library.h"

namespace mx::app {

namespace {

// The file, or ToolLibraryError naming it: a missing, non-regular or oversized file.
QByteArray readToolFile(const QString& path, const QString& shown) {
  try {
    return readBoundedFile(path, kCamToolLibraryFileLimit);
  } catch (const InvalidInput& e) {
    throw ToolLibraryError(toolLibraryError(shown, {}, {}, QString::fromUtf8(e.what())));
  }
}

// Where FreeCAD looks for a library's bit (Path/Tool/library/serializers/fctl.py): the path as given
// (relative to the library's folder), then the Bit/ folder beside the library's folder, by the path and
// by its file name; each also with ".fctb" appended when the path has no suffix.
QStringList bitCandidates(const QDir& library_dir, QString reference) {
  reference.replace('\\', '/');
  const QDir bit_dir(library_dir.filePath(QStringLiteral("../") + kFreeCadBitFolder));
  QStringList paths{library_dir.filePath(reference)};
  if (QFileInfo(reference).isRelative()) paths.append(bit_dir.filePath(reference));
  paths.append(bit_dir.filePath(QFileInfo(reference).fileName()));
  QStringList candidates;
  for (const QString& path : paths)
    for (const QString& candidate : {path, path + ".fctb"}) {
      if (candidate != path && !QFileInfo(path).suffix().isEmpty()) continue;
      const QString clean = QDir::cleanPath(candidate);
      if (!candidates.contains(clean)) candidates.append(clean);
    }
  return candidates;
}

FreeCadBitLoader diskBitLoader(const QString& library_path) {
  const QDir library_dir = QFileInfo(library_path).absoluteDir();
  auto bytes_read = std::make_shared<qint64>(0);
  return [library_dir, bytes_read](const QString& reference) {
    const QStringList candidates = bitCandidates(library_dir, reference);
    for (const QString& candidate : candidates) {
      if (!QFileInfo::exists(candidate)) continue;
      QByteArray bytes = readToolFile(candidate, candidate);
      *bytes_read += bytes.size();
      if (*bytes_read > kMaxFreeCadBitBytes)
        throw ToolLibraryError(QString("the library's bits exceed %1 MB together").arg(kMaxFreeCadBitBytes >> 20));
      return bytes;
    }
    throw ToolLibraryError(QString("%1 not found: looked for %2").arg(quoted(reference), candidates.join(", ")));
  };
}

bool isLibrary(const QString& path, const QByteArray& bytes) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix == "fctl") return true;
  if (suffix == "fctb") return false;
  return QJsonDocument::fromJson(bytes).object().contains("tools");
}

// An export folder stands for its library: the one .fctl in its Library/ folder.
QString libraryOfFolder(const QString& folder) {
  const QDir library_dir(QDir(folder).filePath(kFreeCadLibraryFolder));
  const QStringList libraries = library_dir.entryList({"*.fctl"}, QDir::Files, QDir::Name);
  if (libraries.size() != 1)
    throw ToolLibraryError(toolLibraryError(folder, {}, {},
                                            QString("a folder with %1 libraries in %2/: name the .fctl file")
                                                .arg(libraries.size())
                                                .arg(kFreeCadLibraryFolder)));
  return library_dir.filePath(libraries.front());
}

}  // namespace

ImportedLibrary readFreeCadFile(const QString& given_path, const ToolImportOptions& options) {
  const QString path = QFileInfo(given_path).isDir() ? libraryOfFolder(given_path) : given_path;
  const QString name = QFileInfo(path).fileName();
  const QByteArray bytes = readToolFile(path, name);
  if (isLibrary(path, bytes)) return readFreeCadLibrary(bytes, name, diskBitLoader(path), options);
  return readFreeCadBit(bytes, name, options);
}

QString writeFreeCadFolder(const FreeCadExport& files, const QString& folder) {
  const QFileInfo info(folder);
  if (info.exists() && !info.isDir()) return QString("%1: not a folder").arg(quoted(folder));
  const QDir dir(folder);
  for (const QString& sub : {kFreeCadLibraryFolder, kFreeCadBitFolder})
    if (!dir.mkpath(sub)) return QString("%1: the folder cannot be created").arg(quoted(dir.filePath(sub)));
  std::vector<std::pair<QString, QByteArray>> all{
      {kFreeCadLibraryFolder + '/' + files.libraryName + ".fctl", files.library}};
  all.insert(all.end(), files.bits.begin(), files.bits.end());
  for (const auto& [relative, bytes] : all) {
    const QString problem = writeFileAtomically(dir.filePath(relative), bytes);
    if (!problem.isEmpty()) return QString("%1: %2").arg(relative, problem);
  }
  return {};
}

}  // namespace mx::app
