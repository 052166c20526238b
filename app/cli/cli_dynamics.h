#pragma once
// --dynamics modal|measured, shared by lobes, point, rank and pareto (services/measured_dynamics.h).
#include <QCommandLineParser>
#include <optional>

#include "document/project.h"
#include "services/measured_dynamics.h"

namespace mx::app {

QCommandLineOption dynamicsCommandOption();
// nullopt when the flag is absent (the tool's default); CliError(2) for another value.
std::optional<DynamicsSource> dynamicsOption(const QCommandLineParser& parser);
// "note: ..." on stderr when the measured FRF was asked for and the fitted modes are used.
void reportDynamicsNote(const DynamicsChoice& choice, const QString& tool_id);
// The tool, or ProjectError naming the known ids.
const ToolSpec& requireTool(const Project& project, const QString& tool_id);

}  // namespace mx::app
