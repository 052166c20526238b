#pragma once
// Shared pieces of the CLI subcommands: option parsing with range-checked numbers, JSON output
// and the error type of command-line flags, which carries the exit code (project content throws
// ProjectError, document/project.h; the services throw InputError and ComputationError).
#include <QCommandLineParser>
#include <QJsonObject>
#include <QString>
#include <QTextStream>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>

#include "document/project.h"
#include "expert/expert_settings.h"
#include "services/exit_code.h"
#include "services/json_output.h"

namespace mx::app {

class CliError : public std::runtime_error {
 public:
  CliError(const QString& message, int exitCode) : std::runtime_error(message.toStdString()), code(exitCode) {}
  int code;
};

// `millexpert-cli COMMAND --help`: the command's usage, printed on stdout with exit 0.
class CliHelp : public CliError {
 public:
  explicit CliHelp(const QString& usage) : CliError(usage, kExitOk) {}
};

// Reads --name as a finite number in [min, max]; nullopt when absent. Throws CliError(2) naming
// the flag, the value and the range otherwise.
std::optional<double> numberOption(const QCommandLineParser& parser, const QString& name,
                                   double min = -std::numeric_limits<double>::max(),
                                   double max = std::numeric_limits<double>::max());
std::optional<int> integerOption(const QCommandLineParser& parser, const QString& name, int min, int max);
QString requiredOption(const QCommandLineParser& parser, const QString& name);

// Parses the arguments: throws CliHelp for --help (whatever else is given), CliError(2) on unknown flags.
void parseArguments(QCommandLineParser& parser, const QStringList& arguments);
// parseArguments with one positional argument (the project, or `name` described by `description`),
// returned; CliError(2) unless there is exactly one.
QString parseSubcommand(QCommandLineParser& parser, const QStringList& arguments, const QString& name = "PROJECT",
                        const QString& description = "The .mxproj project file (at most 64 MB).");

// The operating point flags shared by simulate and point: --tool, --speed [rpm], --depth [mm],
// --feed [mm/tooth], range-checked. A flag left out takes the value of the project's operating_point;
// without one, every flag is required.
struct CutPointFlags {
  QString tool;
  double speed_rpm = 0.0;
  double depth_mm = 0.0;
  double feed_mm_per_tooth = 0.0;
};
QList<QCommandLineOption> cutPointOptions();
CutPointFlags readCutPoint(const QCommandLineParser& parser, const std::optional<OperatingPointSpec>& stored);

// The semi-discretization's cost grows with speeds x steps per tooth period (the automatic choice costs
// about 60): at most kMaxSdmWork, about 20 s on a 2-core machine. Throws CliError(2) naming --steps
// and `range` (how the speeds came about) otherwise.
inline constexpr double kMaxSdmWork = 3e5;
void checkSdmWork(double speeds, int steps, const QString& range);

// Applies --method (zoa|sdm) when the parser has it set.
void applyMethodOption(const QCommandLineParser& parser, ExpertSettings& settings);

// Checks the object (checkJsonOutput) and prints it as one compact line on stdout, or hands it to the
// JsonCapture active on this thread.
void printJson(const QJsonObject& object);

// While alive, printJson on this thread stores its object here instead of printing it: `batch` runs a
// command that has no JSON-building function of its own (cli_computations.h) in-process this way.
class JsonCapture {
 public:
  JsonCapture();
  ~JsonCapture();
  JsonCapture(const JsonCapture&) = delete;
  JsonCapture& operator=(const JsonCapture&) = delete;
  std::optional<QJsonObject> object;

 private:
  JsonCapture* outer_;
};

// Writes `lines` (CSV or other text) atomically to `path` (QSaveFile); `flag` names the option in
// errors: not a regular file or a new one (outputFileProblem), cannot open -> CliError(2), write
// failed -> CliError(1). The commands check their outputs before they compute (output_paths.h).
void writeTextFileAtomically(const QString& flag, const QString& path, const std::function<void(QTextStream&)>& write);

}  // namespace mx::app
