#include "cli/cli_dynamics.h"

#include <QTextStream>

#include "cli/cli_support.h"
#include "document/shortened_text.h"
#include "services/service_errors.h"

namespace mx::app {

QCommandLineOption dynamicsCommandOption() {
  return {"dynamics",
          "modal (the tool's modes) or measured (its tap-test FRF: ZOA with delta = 0; otherwise the fitted "
          "modes). Default: modal when the tool has modes, measured otherwise.",
          "DYNAMICS"};
}

std::optional<DynamicsSource> dynamicsOption(const QCommandLineParser& parser) {
  if (!parser.isSet("dynamics")) return std::nullopt;
  try {
    return dynamicsSourceFromName("--dynamics", parser.value("dynamics"));
  } catch (const InputError& e) {
    throw CliError(QString::fromStdString(e.what()), kExitBadInput);
  }
}

void reportDynamicsNote(const DynamicsChoice& choice, const QString& tool_id) {
  if (choice.note.isEmpty()) return;
  QTextStream(stderr) << "note: tool '" << tool_id << "': " << choice.note << "\n";
}

const ToolSpec& requireTool(const Project& project, const QString& tool_id) {
  if (const ToolSpec* tool = project.findTool(tool_id)) return *tool;
  project.setupFor(tool_id);  // throws "tool 'X' not found", naming the known ids
  throw ProjectError(QString("tool %1 not found").arg(quoted(tool_id)));
}

}  // namespace mx::app
