#include "cli/batch_case_runner.h"

#include <QJsonArray>
#include <QLocale>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <exception>

#include "cli/cli_commands.h"
#include "cli/cli_computations.h"
#include "cli/cli_support.h"
#include "core/invalid_input.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {

const QString kProgram = QStringLiteral("millexpert-cli");

int (*commandOf(const QString& computation))(const QStringList&) {
  if (computation == "lobes") return &runLobesCommand;
  if (computation == "point") return &runPointCommand;
  if (computation == "rank") return &runRankCommand;
  return &runParetoCommand;
}

// The command's flags, as its --help lists them.
QStringList commandFlags(const QString& computation) {
  QString help;
  try {
    commandOf(computation)({kProgram, "--help"});
  } catch (const CliHelp& e) {
    help = QString::fromStdString(e.what());
  }
  // Each option's line starts with its names: "  -c <C1,C2,C3>", "  --from <RPM>", "  -h, --help".
  static const QRegularExpression option(R"(^\s+(?:-\S, )?--?([a-z0-9][a-z0-9-]*))");
  QStringList names;
  for (const QString& line : help.split('\n')) {
    const QRegularExpressionMatch m = option.match(line);
    if (m.hasMatch() && m.captured(1) != "help" && m.captured(1) != "help-all") names.append(m.captured(1));
  }
  return names;
}

// Flags a manifest cannot set: the case sets the tool, and a batch records into no learning database.
QString reservedReason(const QString& computation, const QString& flag) {
  if (flag == "tool" && (computation == "lobes" || computation == "point"))
    return "each case sets it: list the tools in \"tools\"";
  if (flag == "db" && computation == "pareto") return "a batch records into no learning database";
  return {};
}

// A number as a user would type it: the shortest text that reads back as the same double.
QString valueText(const QJsonValue& value) {
  return value.isString() ? value.toString() : QString::number(value.toDouble(), 'g', QLocale::FloatingPointShortest);
}

QStringList flagsOf(const QString& computation, const QJsonObject& options) {
  const QStringList known = commandFlags(computation);
  QStringList flags;
  for (auto it = options.begin(); it != options.end(); ++it) {
    const QString flag = QString(it.key()).replace('_', '-');
    const QString field = QString("options.%1").arg(it.key());
    if (!known.contains(flag))
      throw CliError(QString("%1: not a flag of `millexpert-cli %2`; its flags: %3")
                         .arg(field, computation, QStringList(known).replaceInStrings("-", "_").join(", ")),
                     kExitBadInput);
    if (const QString reason = reservedReason(computation, flag); !reason.isEmpty())
      throw CliError(QString("%1: %2").arg(field, reason), kExitBadInput);
    if (it.value().isBool()) {
      if (it.value().toBool()) flags.append("--" + flag);
      continue;
    }
    const QJsonArray values = it.value().isArray() ? it.value().toArray() : QJsonArray{it.value()};
    for (const auto& v : values) flags << "--" + flag << valueText(v);
  }
  return flags;
}

QJsonObject errorJson(int code, const QString& message) {
  return {{"exit_code", code}, {"message", message}};
}

// The exit code and message `millexpert-cli` gives for the exception (cli_application.cpp).
QJsonObject errorOf(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const CliError& e) {
    return errorJson(e.code, QString::fromStdString(e.what()));
  } catch (const ProjectError& e) {
    return errorJson(e.exitCode(), QString::fromStdString(e.what()));
  } catch (const InputError& e) {
    return errorJson(e.exitCode(), QString::fromStdString(e.what()));
  } catch (const ComputationError& e) {
    return errorJson(e.exitCode(), QString::fromStdString(e.what()));
  } catch (const InvalidInput& e) {
    return errorJson(kExitBadInput, QString::fromStdString(e.what()));
  } catch (const std::exception& e) {
    return errorJson(kExitComputationFailed, QString("computation failed: %1").arg(e.what()));
  }
  return errorJson(kExitComputationFailed, "computation failed");
}

// The flags' own errors come before the project is read: a dry run on a missing project shows them.
void checkFlagValues(const QString& computation, const QStringList& flags) {
  QTemporaryDir dir;
  JsonCapture capture;
  try {
    commandOf(computation)(QStringList{kProgram, dir.filePath("flag-check.mxproj")} + flags);
  } catch (const ProjectError&) {  // the missing project: the flags passed
  } catch (...) {
    const QJsonObject error = errorOf(std::current_exception());
    throw CliError(QString("options: %1").arg(error.value("message").toString()), error.value("exit_code").toInt());
  }
}

template <class Json>
QJsonObject parsedAndComputed(const QList<QCommandLineOption>& options, const QStringList& arguments, Json json) {
  QCommandLineParser parser;
  parser.addOptions(options);
  parseArguments(parser, arguments);
  return json(parser);
}

// pareto has no JSON-building function of its own: it runs whole on a copy of the case's project.
QJsonObject paretoJson(const Project& project, const QStringList& flags) {
  QTemporaryDir dir;
  if (!dir.isValid()) throw ComputationError(QString("cannot make a temporary folder: %1").arg(dir.errorString()));
  const QString path = dir.filePath("case.mxproj");
  saveProject(project, path);
  JsonCapture capture;
  runParetoCommand(QStringList{kProgram, path} + flags);
  if (!capture.object) throw ComputationError("pareto printed no result");
  return *capture.object;
}

}  // namespace

BatchCaseRunner::BatchCaseRunner(const QString& computation, const QJsonObject& options)
    : computation_(computation), flags_(flagsOf(computation, options)) {
  checkFlagValues(computation_, flags_);
}

QJsonObject BatchCaseRunner::compute(const Project& project, const QString& tool, BatchCaseOutcome& outcome) const {
  const QStringList arguments = QStringList{kProgram} + flags_ + QStringList{"--tool", tool};
  if (computation_ == "lobes")
    return parsedAndComputed(lobesOptions(), arguments, [&](const auto& p) { return lobesJson(p, project); });
  if (computation_ == "point")
    return parsedAndComputed(pointOptions(), arguments, [&](const auto& p) { return pointJson(p, project); });
  if (computation_ == "pareto") return paretoJson(project, flags_);
  return parsedAndComputed(rankOptions(), QStringList{kProgram} + flags_, [&](const auto& p) {
    const RankOutput output = rankJson(p, project);
    if (!output.unresolved_chatter.isEmpty())
      outcome.error = errorJson(kExitComputationFailed, output.unresolved_chatter);
    return output.json;
  });
}

BatchCaseOutcome BatchCaseRunner::run(const Project& project, const QString& tool) const {
  BatchCaseOutcome outcome;
  try {
    const QJsonObject json = compute(project, tool, outcome);
    checkJsonOutput(json);
    outcome.result = json;
  } catch (...) {
    outcome.error = errorOf(std::current_exception());
  }
  return outcome;
}

}  // namespace mx::app
