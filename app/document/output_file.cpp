#include "document/output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <QFileInfo>
#include <QSaveFile>
#include <cerrno>
#include <cstring>

#include "core/input_file.h"
#include "document/frf_paths.h"
#include "document/project.h"
#include "document/shortened_text.h"

namespace mx::app {

namespace {

bool isWritable(const QString& path) {
  return ::access(QFile::encodeName(path).constData(), W_OK) == 0;
}

// The folder a new file would be created in (QSaveFile writes its temporary file there too).
QString folderProblem(const QString& folder) {
  struct stat st {};
  if (::stat(QFile::encodeName(folder).constData(), &st) != 0 || !S_ISDIR(st.st_mode))
    return QString("the folder %1 does not exist").arg(quoted(folder));
  if (!isWritable(folder)) return QString("the folder %1 is not writable").arg(quoted(folder));
  return {};
}

// Where a path leads: the device and inode of an existing file (through every symbolic link), and a
// canonical path (of the file, or of the folder a new file would be created in, and its name).
struct FileIdentity {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  QString canonical;

  bool sameAs(const FileIdentity& other) const {
    if (exists && other.exists) return device == other.device && inode == other.inode;
    return !exists && !other.exists && canonical == other.canonical;
  }
};

FileIdentity identityOf(const QString& path) {
  FileIdentity id;
  struct stat st {};
  const QFileInfo info(path);
  if (::stat(QFile::encodeName(path).constData(), &st) == 0) {
    id.exists = true;
    id.device = st.st_dev;
    id.inode = st.st_ino;
    id.canonical = info.canonicalFilePath();
  } else {
    const QString folder = QFileInfo(info.absolutePath()).canonicalFilePath();
    id.canonical = (folder.isEmpty() ? info.absolutePath() : folder) + '/' + info.fileName();
  }
  return id;
}

QString refusal(const NamedPath& output, const QString& why) {
  return QString("%1 = %2: %3").arg(output.name, quoted(output.path), why);
}

}  // namespace

QString outputPathsProblem(const QList<NamedPath>& outputs, const QList<NamedPath>& inputs) {
  QList<FileIdentity> input_ids;
  for (const NamedPath& in : inputs) input_ids.append(identityOf(in.path));
  for (qsizetype o = 0; o < outputs.size(); ++o) {
    const NamedPath& out = outputs[o];
    if (out.path.isEmpty()) return refusal(out, "no file name");
    const FileIdentity id = identityOf(out.path);
    for (qsizetype i = 0; i < inputs.size(); ++i)
      if (id.sameAs(input_ids[i]))
        return refusal(out,
                       QString("the same file as %1, which this command reads: an output never overwrites an input")
                           .arg(inputs[i].name));
    for (qsizetype other = 0; other < o; ++other)
      if (id.sameAs(identityOf(outputs[other].path)))
        return refusal(out,
                       QString("the same file as %1: each output needs a file of its own").arg(outputs[other].name));
    if (const QString problem = outputFileProblem(out.path); !problem.isEmpty())
      return refusal(out, problem + ": only a regular file, or a new file in an existing writable folder, is written");
  }
  return {};
}

QList<NamedPath> projectInputFiles(const Project& project) {
  QList<NamedPath> files;
  for (std::size_t i = 0; i < project.tools.size(); ++i) {
    const ToolSpec& tool = project.tools[i];
    for (const auto& [ref, axis] : {std::pair{&tool.frf_x, "frf_x"}, {&tool.frf_y, "frf_y"}})
      if (*ref)
        files.append({QString("tools[%1].%2 (the tap test of tool %3)").arg(i).arg(axis, quoted(tool.id)),
                      resolvedFrfPath(project, **ref)});
  }
  return files;
}

QString outputFileProblem(const QString& path) {
  if (path.isEmpty()) return "no file name";
  const QByteArray native = QFile::encodeName(path);
  struct stat st {};
  if (::stat(native.constData(), &st) != 0) {
    if (::lstat(native.constData(), &st) == 0) return "a symbolic link to a missing file";
    return folderProblem(QFileInfo(path).absolutePath());
  }
  if (!S_ISREG(st.st_mode)) {
    const std::string_view kind = nonRegularFileKind(st.st_mode);
    return QString::fromLatin1(kind.data(), static_cast<qsizetype>(kind.size())) + ", not a regular file";
  }
  if (!isWritable(path)) return "the file is not writable";
  return folderProblem(QFileInfo(QFileInfo(path).canonicalFilePath()).absolutePath());
}

QString writeFileAtomically(const QString& path, const QByteArray& bytes) {
  if (QString problem = outputFileProblem(path); !problem.isEmpty()) return problem;
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly)) return file.errorString();
  // QSaveFile buffers: a full disk (or a file-size limit) shows only when the buffer is flushed, and
  // commit() would rename the torn file into place, so the flush is checked before it.
  errno = 0;
  if (file.write(bytes) != bytes.size() || !file.flush()) {
    QString reason = errno != 0 ? QString::fromLocal8Bit(std::strerror(errno)) : file.errorString();
    file.cancelWriting();
    return reason;
  }
  if (!file.commit()) return file.errorString();
  return {};
}

}  // namespace mx::app
