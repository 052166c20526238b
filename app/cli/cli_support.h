#pragma once
// Shared pieces of the CLI subcommands: option parsing with range-checked numbers, JSON output
// and the error type that carries the exit code.
#include <QCommandLineParser>
#include <QJsonObject>
#include <QString>
#include <QTextStream>
#include <functional>
#include <limits>
#include <optional>
#include <utility>
#include <vector>
#include <stdexcept>

namespace mx::app {

class CliError : public std::runtime_error {
 public:
  CliError(const QString& message, int exitCode) : std::runtime_error(message.toStdString()), code(exitCode) {}
  int code;
};

// Reads --name as a finite number in [min, max]; nullopt when absent. Throws CliError(2) naming
// the flag, the value and the range otherwise.
std::optional<double> numberOption(const QCommandLineParser& parser, const QString& name,
                                   double min = -std::numeric_limits<double>::max(),
                                   double max = std::numeric_limits<double>::max());
std::optional<int> integerOption(const QCommandLineParser& parser, const QString& name, int min, int max);
QString requiredOption(const QCommandLineParser& parser, const QString& name);

// Parses the subcommand's arguments; throws CliError(2) on unknown flags or a missing PROJECT.
QString parseSubcommand(QCommandLineParser& parser, const QStringList& arguments);

// The operating point flags shared by simulate and point: --tool, --speed [rpm], --depth [mm],
// --feed [mm/tooth], all required and range-checked.
struct CutPointFlags {
  QString tool;
  double speed_rpm = 0.0;
  double depth_mm = 0.0;
  double feed_mm_per_tooth = 0.0;
};
QList<QCommandLineOption> cutPointOptions();
CutPointFlags readCutPoint(const QCommandLineParser& parser);

void printJson(const QJsonObject& object);

// Writes `lines` (CSV or other text) atomically to `path` (QSaveFile); `flag` names the option in
// errors: cannot open -> CliError(2), write failed -> CliError(1).
void writeTextFileAtomically(const QString& flag, const QString& path, const std::function<void(QTextStream&)>& write);

// A depth profile along the feed path: a non-empty array of {"length_mm" (0, 1e7], "depth_mm" [0, 1000]}
// at `path`, as (length, depth) pairs in metres. CliError(2) naming the element.
std::vector<std::pair<double, double>> depthStepsField(const QJsonValue& value, const QString& path);

// Project sections: "<field> = <value>: must be <range>" as CliError(2).
[[noreturn]] void failField(const QString& field, const QString& value, const QString& range);
// o[key] as a finite number in [lo, hi] ("path.key" in messages); `fallback` when absent, else an
// error naming the missing field.
double sectionNumber(const QJsonObject& o, const QString& path, const QString& key, double lo, double hi,
                     const QString& range, std::optional<double> fallback = {});

// JSON number, or null for a non-finite value (never NaN in output).
QJsonValue jsonNumberOrNull(double value);

}  // namespace mx::app
