#include "cli/cli_support.h"

#include <QJsonDocument>
#include <QSaveFile>
#include <QTextStream>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "cli/cli_application.h"
#include "document/output_file.h"
#include "document/project.h"
#include "document/shortened_text.h"
#include "services/expert_request.h"

namespace mx::app {

std::optional<double> numberOption(const QCommandLineParser& parser, const QString& name, double min, double max) {
  if (!parser.isSet(name)) return std::nullopt;
  const QString text = parser.value(name);
  bool ok = false;
  const double value = text.toDouble(&ok);
  if (!ok || !std::isfinite(value))
    throw CliError(QString("--%1 = %2: not a finite number").arg(name, quoted(text)), kExitBadInput);
  if (value < min || value > max)
    throw CliError(QString("--%1 = %2: must be in [%3, %4]").arg(name, shortened(text)).arg(min).arg(max),
                   kExitBadInput);
  return value;
}

std::optional<int> integerOption(const QCommandLineParser& parser, const QString& name, int min, int max) {
  if (!parser.isSet(name)) return std::nullopt;
  const QString text = parser.value(name);
  bool ok = false;
  const int value = text.toInt(&ok);
  if (!ok) throw CliError(QString("--%1 = %2: not an integer").arg(name, quoted(text)), kExitBadInput);
  if (value < min || value > max)
    throw CliError(QString("--%1 = %2: must be an integer in [%3, %4]").arg(name, shortened(text)).arg(min).arg(max),
                   kExitBadInput);
  return value;
}

QString requiredOption(const QCommandLineParser& parser, const QString& name) {
  if (!parser.isSet(name)) throw CliError(QString("--%1 is required").arg(name), kExitBadInput);
  return parser.value(name);
}

void parseArguments(QCommandLineParser& parser, const QStringList& arguments) {
  const bool parsed = parser.parse(arguments);
  const bool help = arguments.contains("--help") || arguments.contains("-h") || arguments.contains("-?");
  if (help) throw CliHelp(parser.helpText());
  if (!parsed) throw CliError(parser.errorText(), kExitBadInput);
}

QString parseSubcommand(QCommandLineParser& parser, const QStringList& arguments, const QString& name,
                        const QString& description) {
  parser.addPositionalArgument(name, description);
  parseArguments(parser, arguments);
  const QStringList positional = parser.positionalArguments();
  if (positional.size() != 1)
    throw CliError(QString("expected exactly one %1 argument, got %2").arg(name).arg(positional.size()), kExitBadInput);
  return positional.front();
}

QList<QCommandLineOption> cutPointOptions() {
  const QString stored = " (default: the project's operating_point; required without one).";
  return {{"tool", "Tool id" + stored, "ID"},
          {"speed", "Spindle speed [rpm], 1..1e5" + stored, "RPM"},
          {"depth", "Axial depth of cut [mm], 0..1000" + stored, "MM"},
          {"feed", "Feed per tooth [mm/tooth], 1e-6..10" + stored, "MM_PER_TOOTH"}};
}

CutPointFlags readCutPoint(const QCommandLineParser& parser, const std::optional<OperatingPointSpec>& stored) {
  if (!stored) {
    for (const char* flag : {"tool", "speed", "depth", "feed"})
      if (!parser.isSet(flag))
        throw CliError(QString("--%1 is required: the project has no operating_point to default to").arg(flag),
                       kExitBadInput);
  }
  CutPointFlags p;
  p.tool = parser.isSet("tool") ? parser.value("tool") : stored->tool;
  p.speed_rpm = numberOption(parser, "speed", 1.0, 1e5).value_or(stored ? stored->speed_rpm : 0.0);
  p.depth_mm = numberOption(parser, "depth", 0.0, 1000.0).value_or(stored ? stored->depth_mm : 0.0);
  p.feed_mm_per_tooth = numberOption(parser, "feed", 1e-6, 10.0).value_or(stored ? stored->feed_mm_per_tooth : 0.0);
  return p;
}

void checkSdmWork(double speeds, int steps, const QString& range) {
  constexpr int kAutomaticStepsCost = 60;
  const int cost = steps > 0 ? steps : kAutomaticStepsCost;
  const double work = speeds * cost;
  if (work <= kMaxSdmWork) return;
  const QString stepsText = steps > 0 ? QString("--steps %1").arg(steps) : QString("the automatic steps (about 60)");
  throw CliError(QString("--method sdm: %1 speeds (%2) x %3 = %4 speed-steps, at most %5 (about 20 s): lower --steps "
                         "or use fewer speeds")
                     .arg(speeds, 0, 'f', 0)
                     .arg(range, stepsText)
                     .arg(work, 0, 'g', 3)
                     .arg(kMaxSdmWork, 0, 'g', 3),
                 kExitBadInput);
}

namespace {
thread_local JsonCapture* active_capture = nullptr;
}  // namespace

JsonCapture::JsonCapture() : outer_(active_capture) {
  active_capture = this;
}

JsonCapture::~JsonCapture() {
  active_capture = outer_;
}

void printJson(const QJsonObject& object) {
  checkJsonOutput(object);
  if (active_capture != nullptr) {
    active_capture->object = object;
    return;
  }
  QTextStream out(stdout);
  out << QJsonDocument(object).toJson(QJsonDocument::Compact) << Qt::endl;
}

void applyMethodOption(const QCommandLineParser& parser, ExpertSettings& settings) {
  if (parser.isSet("method")) settings.stability.method = stabilityMethodFromText(parser.value("method"), "--method");
}

void writeTextFileAtomically(const QString& flag, const QString& path, const std::function<void(QTextStream&)>& write) {
  if (const QString problem = outputFileProblem(path); !problem.isEmpty())
    throw CliError(QString("%1 = %2: %3").arg(flag, quoted(path), problem), kExitBadInput);
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
    throw CliError(QString("%1 = %2: cannot write (%3)").arg(flag, quoted(path), file.errorString()), kExitBadInput);
  QTextStream out(&file);
  out.setRealNumberPrecision(10);
  write(out);
  out.flush();
  errno = 0;
  if (!file.flush()) {  // before commit(), which would rename a torn file into place (QSaveFile buffers)
    const QString reason = errno != 0 ? QString::fromLocal8Bit(std::strerror(errno)) : file.errorString();
    file.cancelWriting();
    throw CliError(QString("%1 = %2: write failed (%3)").arg(flag, quoted(path), reason), kExitComputationFailed);
  }
  if (!file.commit())
    throw CliError(QString("%1 = %2: write failed (%3)").arg(flag, quoted(path), file.errorString()),
                   kExitComputationFailed);
}

}  // namespace mx::app
