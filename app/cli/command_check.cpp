// millexpert-cli check PROJECT: exit 0 with a summary (name, tools, the stored operating_point), or exit 2
// with the validation message.
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
  QJsonObject out{{"valid", true}, {"name", project.name}, {"tools", tools}};
  if (const std::optional<OperatingPointSpec>& p = project.operating_point)
    out.insert("operating_point", QJsonObject{{"tool", p->tool},
                                              {"speed_rpm", p->speed_rpm},
                                              {"depth_mm", p->depth_mm},
                                              {"feed_mm_per_tooth", p->feed_mm_per_tooth}});
  printJson(out);
  return kExitOk;
}

}  // namespace mx::app
