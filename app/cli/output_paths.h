#pragma once
// The CLI's side of "outputs never destroy inputs" (outputPathsProblem, document/output_file.h): each
// command lists the files it reads and writes, and before it computes or writes anything an output is
// refused with exit 2 when it is an input (the project, a part program, a tap-test file the project
// names; also through a symbolic or hard link), another output, or an existing file that is not a
// regular one (device, FIFO, directory, socket), or new in a folder that is missing or not writable.
// What passes is written atomically (writeTextFileAtomically, saveFrfFile).
#include <QCommandLineParser>
#include <QList>
#include <QString>

#include "document/output_file.h"
#include "document/project.h"

namespace mx::app {

class OutputPaths {
 public:
  // A file the command reads; `role` names it in refusals ("PROJECT", "PROGRAM").
  OutputPaths& input(const QString& role, const QString& path);
  // A file the command writes, named by its flag ("--csv").
  OutputPaths& output(const QString& flag, const QString& path);
  // output("--name", value) when the option is set.
  OutputPaths& outputOption(const QCommandLineParser& parser, const QString& name);

  // Throws CliError(2) naming the flag, the path and why, on the first output refused.
  void check() const;

  // check(), then loadProject(path), then check() against the files the project names as well.
  Project loadProject(const QString& path);

 private:
  QList<NamedPath> inputs_;
  QList<NamedPath> outputs_;
};

}  // namespace mx::app
