// millexpert-cli frf-export PROJECT --tool ID --output FILE [--axis x|y|xy] [--source modes|measured]
//                           [--format uff58|uff58b|csv] [--quantity Q] [--from HZ] [--to HZ] [--step HZ]
//                           [--noise-pct P] [--seed N]
//   {"output", "format", "source", "datasets": [{"direction", "quantity", "points", "from_Hz", "to_Hz"}]}
// The tool's FRF per axis (one dataset each, x before y): its modes' receptance on the even grid
// from..to by step (default 0 Hz to twice the highest mode, 1 Hz), or its measured FRF (frf_x, frf_y)
// at the measured lines; as receptance (default), mobility or accelerance; optionally with complex
// noise of RMS P % relative to |H| (synthetic tap tests). Written atomically. Exit 2: bad flags, an
// axis without modes or FRF, an unwritable file.
#include <QJsonArray>
#include <algorithm>
#include <cmath>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_dynamics.h"
#include "cli/cli_support.h"
#include "cli/output_paths.h"
#include "document/project.h"
#include "document/shortened_text.h"
#include "frf/modal_frf.h"
#include "frf/receptance_conversion.h"
#include "services/frf_export.h"
#include "services/frf_import.h"
#include "services/service_errors.h"

namespace mx::app {

namespace {

struct ExportRequest {
  QString tool;
  QString output;
  std::vector<FrfDirection> axes;
  bool measured = false;
  FrfFormat format = FrfFormat::Uff58;
  FrfQuantity quantity = FrfQuantity::Receptance;
  std::optional<double> from_hz, to_hz, step_hz;
  double noise = 0.0;
  int seed = 1;
};

ExportRequest readRequest(const QCommandLineParser& parser) {
  ExportRequest r;
  r.tool = requiredOption(parser, "tool");
  r.output = requiredOption(parser, "output");
  const QString axis = parser.value("axis");
  if (axis == "xy") {
    r.axes = {FrfDirection::X, FrfDirection::Y};
  } else if (axis == "x" || axis == "y") {
    r.axes = {frfAxisFromName("--axis", axis)};
  } else {
    throw CliError(QString("--axis = %1: must be x, y or xy").arg(quoted(axis, u'"')), kExitBadInput);
  }
  const QString source = parser.value("source");
  if (source != "modes" && source != "measured")
    throw CliError(QString("--source = %1: must be modes or measured").arg(quoted(source, u'"')), kExitBadInput);
  r.measured = source == "measured";
  r.format = frfFormatFromName("--format", parser.value("format"));
  r.quantity = frfQuantityFromName("--quantity", parser.value("quantity"));
  r.from_hz = numberOption(parser, "from", 0.0, 1e6);
  r.to_hz = numberOption(parser, "to", 1e-3, 1e6);
  r.step_hz = numberOption(parser, "step", 1e-6, 1e6);
  r.noise = numberOption(parser, "noise-pct", 0.0, 100.0).value_or(0.0) / 100.0;
  r.seed = integerOption(parser, "seed", 0, 2147483647).value_or(1);
  return r;
}

const char* axisName(FrfDirection d) {
  return d == FrfDirection::X ? "x" : "y";
}

std::vector<double> exportGrid(const ExportRequest& r, const ModalAxis& modes) {
  double highest = 0.0;
  for (const Mode& m : modes) highest = std::max(highest, m.natural_frequency_hz);
  const double from = r.from_hz.value_or(0.0);
  const double to = r.to_hz.value_or(std::ceil(2.0 * highest / 100.0) * 100.0);
  const double step = r.step_hz.value_or(1.0);
  if (!(to > from)) throw CliError(QString("--to = %1: must be > --from (%2)").arg(to).arg(from), kExitBadInput);
  if ((to - from) / step > 1e6)
    throw CliError(QString("--step = %1: gives more than 1000000 lines").arg(step), kExitBadInput);
  std::vector<double> f;
  const auto n = static_cast<std::size_t>(std::floor((to - from) / step + 1e-9)) + 1;
  f.reserve(n);
  for (std::size_t i = 0; i < n; ++i) f.push_back(from + static_cast<double>(i) * step);
  return f;
}

Receptance axisReceptance(const ExportRequest& r, const Project& project, const ToolSpec& tool, FrfDirection axis) {
  const QString field = QString("frf_") + axisName(axis);
  if (r.measured) {
    const std::optional<FrfRefSpec>& ref = axis == FrfDirection::X ? tool.frf_x : tool.frf_y;
    if (!ref)
      throw InputError(
          QString("tool %1: %2 is not given: --source measured needs a tap-test FRF").arg(quoted(tool.id), field));
    MeasuredAxis m = loadMeasuredAxis(project, tool, field, *ref);
    return {axis, axis, std::move(m.frequency_hz), std::move(m.h_m_per_n)};
  }
  const MillingSetup setup = project.setupFor(tool.id);
  const ModalAxis& modes = axis == FrfDirection::X ? setup.modes_x : setup.modes_y;
  if (modes.empty())
    throw InputError(QString("tool %1: modes_%2 is empty: nothing to export from modes (--source measured exports "
                             "the tap-test FRF)")
                         .arg(quoted(tool.id), axisName(axis)));
  const FrfDataset d = modalFrfDataset(modes, FrfQuantity::Receptance, exportGrid(r, modes), axis, {});
  return {axis, axis, d.frequency_hz, d.values};
}

QJsonObject datasetJson(const FrfDataset& d) {
  return {{"direction", axisName(d.response_direction)},
          {"quantity", QString::fromLatin1(frfQuantityName(d.quantity).data())},
          {"points", static_cast<qint64>(d.frequency_hz.size())},
          {"from_Hz", d.frequency_hz.front()},
          {"to_Hz", d.frequency_hz.back()}};
}

}  // namespace

int runFrfExportCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Write a tool's FRF (from its modes or its tap test) as UFF 58, 58b or CSV.");
  parser.addHelpOption();
  parser.addOptions({
      {"tool", "Tool id.", "ID"},
      {"output", "The file to write.", "FILE"},
      {"axis", "x, y or xy (one dataset each; CSV takes one axis). Default xy.", "AXIS", "xy"},
      {"source", "modes (the tool's modes) or measured (its frf_x / frf_y). Default modes.", "SOURCE", "modes"},
      {"format", "uff58 (ASCII), uff58b (binary) or csv. Default uff58.", "FORMAT", "uff58"},
      {"quantity", "receptance, mobility or accelerance. Default receptance.", "Q", "receptance"},
      {"from", "First line [Hz] (modes only; default 0).", "HZ"},
      {"to", "Last line [Hz] (modes only; default twice the axis's highest mode, rounded up to 100 Hz).", "HZ"},
      {"step", "Line spacing [Hz] (modes only; default 1).", "HZ"},
      {"noise-pct", "Complex noise, RMS relative to |H| [%] (default 0).", "P"},
      {"seed", "Seed of the noise (default 1).", "N"},
  });
  const QString path = parseSubcommand(parser, arguments);
  const ExportRequest request = readRequest(parser);
  const Project project = OutputPaths().output("--output", request.output).loadProject(path);
  const ToolSpec* tool = &requireTool(project, request.tool);
  std::vector<FrfDataset> datasets;
  QJsonArray written;
  for (const FrfDirection axis : request.axes) {
    const Receptance r = axisReceptance(request, project, *tool, axis);
    FrfDataset d = fromReceptance(r, request.quantity, QString("%1 %2").arg(tool->id, axisName(axis)).toStdString());
    if (request.noise > 0.0)
      addRelativeNoise(d.values, request.noise, static_cast<std::uint32_t>(request.seed) + (axis == FrfDirection::Y));
    d.index = static_cast<int>(datasets.size()) + 1;
    written.append(datasetJson(d));
    datasets.push_back(std::move(d));
  }
  saveFrfFile(request.output, request.format, datasets);
  printJson({{"output", request.output},
             {"format", frfFormatName(request.format)},
             {"source", request.measured ? "measured" : "modes"},
             {"datasets", written}});
  return kExitOk;
}

}  // namespace mx::app
