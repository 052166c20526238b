#pragma once
// Every file MillExpert writes is written atomically (QSaveFile: a temporary file in the same folder,
// then a rename). A rename replaces whatever the path names, so a device node, a FIFO or a socket would
// become a regular file: only a regular file, or a new file in an existing writable folder, is written.
#include <QByteArray>
#include <QList>
#include <QString>

namespace mx::app {

struct Project;

// Why `path` must not be written, empty when it may be: "a character device, not a regular file",
// "a directory, not a regular file", "a symbolic link to a missing file", "the file is not writable",
// "the folder '…' does not exist", "the folder '…' is not writable".
QString outputFileProblem(const QString& path);

// Outputs never destroy inputs: each output of a command is checked against the files the command
// reads, against the other outputs, and by outputFileProblem. Files are the same when their device and inode are
// (through every symbolic link, and for hard links), or, when neither exists yet, their canonical paths are.
struct NamedPath {
  QString name;  // "PROJECT", "--csv": how messages name the file
  QString path;
};
// The first refusal, "--csv = '<path, shortened>': <why>", or an empty string when every output may be
// written. Nothing is written or read.
QString outputPathsProblem(const QList<NamedPath>& outputs, const QList<NamedPath>& inputs);

// The files a project names and its commands read: the tools' tap tests (frf_x, frf_y), resolved.
QList<NamedPath> projectInputFiles(const Project& project);

// Writes `bytes` to `path` atomically after outputFileProblem; returns why it was not written (the
// caller names the file), or an empty string when it was.
QString writeFileAtomically(const QString& path, const QByteArray& bytes);

}  // namespace mx::app
