// millexpert-cli frf-info FILE [--quantity Q]
//   {"format": "uff58"|"uff58b"|"csv", "datasets": [{"index", "response_direction", "reference_direction",
//   "quantity", "points", "from_Hz", "to_Hz"}], "skipped_datasets", "skipped_functions"}; "index" counts the
//   file's FRF datasets from 0 (the project's "dataset"), "file_dataset" is its 1-based place in the file.
// millexpert-cli frf-fit FILE [--dataset I] [--quantity Q] [--from HZ] [--to HZ] [--modes N]
//                              [--method lscf|peak]
//   {"modes": [{"freq_Hz", "damping_pct", "stiffness_N_per_um"}], "fit_error_pct", "method"}, modes sorted by
//   frequency; without --modes the order is chosen from the stabilisation diagram (engine/modal_fit).
// --quantity (receptance|mobility|accelerance) is required for CSV and must agree with a UFF file.
// Exit 2: unreadable or malformed file (the message names the line or byte), bad flags; exit 1: no fit.
#include <QJsonArray>
#include <algorithm>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "document/shortened_text.h"
#include "services/frf_import.h"

namespace mx::app {

namespace {

const char* kFileDescription = "The tap-test file: universal file 58/58b or CSV (at most 64 MB).";

QString name(std::string_view text) {
  return QString::fromLatin1(text.data(), static_cast<qsizetype>(text.size()));
}

QCommandLineOption quantityOption() {
  return {"quantity", "The FRF's quantity: receptance, mobility or accelerance (required for CSV).", "Q"};
}

std::optional<FrfQuantity> readQuantity(const QCommandLineParser& parser) {
  if (!parser.isSet("quantity")) return std::nullopt;
  return frfQuantityFromName("--quantity", parser.value("quantity"));
}

QJsonObject datasetJson(const FrfDataset& d, int index) {
  return {{"index", index},
          {"file_dataset", d.index},
          {"response_direction", name(frfDirectionName(d.response_direction))},
          {"reference_direction", name(frfDirectionName(d.reference_direction))},
          {"response_node", d.response_node},
          {"reference_node", d.reference_node},
          {"quantity", name(frfQuantityName(d.quantity))},
          {"points", static_cast<qint64>(d.frequency_hz.size())},
          {"from_Hz", d.frequency_hz.front()},
          {"to_Hz", d.frequency_hz.back()}};
}

ModalFitSettings::Method readMethod(const QCommandLineParser& parser) {
  const QString method = parser.value("method");
  if (method.isEmpty() || method == "lscf") return ModalFitSettings::Method::Lscf;
  if (method == "peak") return ModalFitSettings::Method::Peak;
  throw CliError(QString("--method = %1: must be lscf or peak").arg(quoted(method, u'"')), kExitBadInput);
}

}  // namespace

int runFrfInfoCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("The FRF datasets of a tap-test file (universal file 58/58b or CSV).");
  parser.addHelpOption();
  parser.addOption(quantityOption());
  const QString path = parseSubcommand(parser, arguments, "FILE", kFileDescription);
  const FrfFile file = loadFrfFile(path, readQuantity(parser));
  QJsonArray datasets;
  for (std::size_t i = 0; i < file.datasets.size(); ++i)
    datasets.append(datasetJson(file.datasets[i], static_cast<int>(i)));
  printJson({{"format", frfFormatName(file.format)},
             {"datasets", datasets},
             {"skipped_datasets", file.skipped_datasets},
             {"skipped_functions", file.skipped_functions}});
  return kExitOk;
}

int runFrfFitCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Modes fitted to one FRF of a tap-test file (LSCF + LSFD + refinement).");
  parser.addHelpOption();
  parser.addOptions({
      {"dataset", "The FRF dataset, counted from 0 among the file's FRFs (default 0).", "I"},
      quantityOption(),
      {"from", "Lower end of the fitting band [Hz] (default: the first measured frequency above 0).", "HZ"},
      {"to", "Upper end of the fitting band [Hz] (default: the last measured frequency).", "HZ"},
      {"modes", "Number of modes to keep, 1..40 (default: chosen from the stabilisation diagram).", "N"},
      {"method", "lscf (default) or peak (half-power peak picking).", "M"},
  });
  const QString path = parseSubcommand(parser, arguments, "FILE", kFileDescription);
  const std::optional<int> dataset = integerOption(parser, "dataset", 0, 1000000);
  const std::optional<double> from_hz = numberOption(parser, "from", 0.0, 1e7);
  const std::optional<double> to_hz = numberOption(parser, "to", 0.0, 1e7);
  ModalFitSettings settings;
  settings.modes = integerOption(parser, "modes", 1, 40);
  if (settings.modes) settings.max_modes = std::max(settings.max_modes, *settings.modes);
  settings.method = readMethod(parser);
  const FrfFile file = loadFrfFile(path, readQuantity(parser));
  const Receptance receptance = frfReceptance(file, path, dataset.value_or(0));
  const ModalFitResult fit = fitFrfModes(receptance, from_hz, to_hz, settings);
  QJsonArray modes;
  for (const Mode& m : fit.modes)
    modes.append(QJsonObject{{"freq_Hz", m.natural_frequency_hz},
                             {"damping_pct", m.damping_ratio * 100.0},
                             {"stiffness_N_per_um", m.stiffness_n_per_m * 1e-6}});
  printJson({{"modes", modes},
             {"fit_error_pct", fit.fit_error_pct},
             {"method", QString::fromStdString(fit.method)},
             {"dataset", dataset.value_or(0)},
             {"response_direction", name(frfDirectionName(receptance.direction))},
             {"from_Hz", fit.band_frequency_hz.empty() ? 0.0 : fit.band_frequency_hz.front()},
             {"to_Hz", fit.band_frequency_hz.empty() ? 0.0 : fit.band_frequency_hz.back()}});
  return kExitOk;
}

}  // namespace mx::app
