#include "cli/output_paths.h"

#include "cli/cli_support.h"

namespace mx::app {

OutputPaths& OutputPaths::input(const QString& role, const QString& path) {
  inputs_.append({role, path});
  return *this;
}

OutputPaths& OutputPaths::output(const QString& flag, const QString& path) {
  outputs_.append({flag, path});
  return *this;
}

OutputPaths& OutputPaths::outputOption(const QCommandLineParser& parser, const QString& name) {
  if (parser.isSet(name)) output("--" + name, parser.value(name));
  return *this;
}

void OutputPaths::check() const {
  if (const QString problem = outputPathsProblem(outputs_, inputs_); !problem.isEmpty())
    throw CliError(problem, kExitBadInput);
}

Project OutputPaths::loadProject(const QString& path) {
  input("PROJECT", path);
  check();
  Project project = app::loadProject(path);
  inputs_.append(projectInputFiles(project));
  check();
  return project;
}

}  // namespace mx::app
