// millexpert-cli check PROJECT: exit 0 with a summary, or exit 2 with the validation message.
#include <QJsonArray>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "document/project.h"

namespace mx::app {

int runCheckCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Validate a MillExpert project file.");
  parser.addHelpOption();
  const QString path = parseSubcommand(parser, arguments);
  const Project project = loadProject(path);
  QJsonArray tools;
  for (const ToolSpec& t : project.tools) tools.append(t.id);
  printJson({{"valid", true}, {"name", project.name}, {"tools", tools}});
  return kExitOk;
}

}  // namespace mx::app
