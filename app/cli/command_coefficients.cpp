// millexpert-cli coefficients FILE... --diameter MM --teeth N --depth MM [--immersion A_D] [--milling up|down]
//                                      [--speed RPM]... [--feed MM_PER_TOOTH]...
// The cutting coefficients of test cuts by the average-force method (engine/cutting_data). A FILE, told by
// its content, is the mean forces of several cuts (CSV header feed_mm_per_tooth,Fx_N,Fy_N,Fz_N) or the
// dynamometer record of one cut: a CSV (header time_s,Fx_N,Fy_N,Fz_N) or a universal file of three
// datasets 58/58b of function type 1, time responses of Fx, Fy and Fz (force_record_uff.h). A record is
// averaged over whole revolutions and needs its spindle speed and feed: --speed and --feed once for every
// record, or once per record in the order of the files. Prints {"Kt_N_mm2", "Kr", "Ka_N_mm2", "Kte_N_mm",
// "Kre_N_mm", "Kae_N_mm", "r2": {"x", "y", "z"}, "residuals_N": [{"feed_mm_per_tooth", "x", "y", "z"}]} plus
// "Krc_N_mm2", "ci95" (half-widths of the 95 % confidence intervals of the same keys; 0 with two cuts) and
// "cuts". Kt_N_mm2 is K_tc and Kr is K_rc / K_tc: the material fields. Exit 2: a bad file (the message names
// the line) or flag; exit 1: no fit.
#include <QJsonArray>
#include <algorithm>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "core/invalid_input.h"
#include "cutting_data/force_measurement_csv.h"
#include "cutting_data/force_record_uff.h"
#include "document/input_files.h"

namespace mx::app {

namespace {

double requiredNumber(const QCommandLineParser& parser, const QString& name, double min, double max) {
  const std::optional<double> v = numberOption(parser, name, min, max);
  if (!v) throw CliError(QString("--%1 is required").arg(name), kExitBadInput);
  return *v;
}

TestCutSetup readSetup(const QCommandLineParser& parser) {
  TestCutSetup s;
  s.diameter_m = requiredNumber(parser, "diameter", 1e-3, 1e4) * 1e-3;
  const std::optional<int> teeth = integerOption(parser, "teeth", 1, MillingSetup::kMaxTeeth);
  if (!teeth) throw CliError("--teeth is required", kExitBadInput);
  s.teeth = *teeth;
  s.depth_m = requiredNumber(parser, "depth", 1e-3, 1e3) * 1e-3;
  s.radial_ratio = numberOption(parser, "immersion", 1e-3, 1.0).value_or(1.0);
  const QString milling = parser.value("milling");
  if (!milling.isEmpty() && milling != "up" && milling != "down")
    throw CliError(QString("--milling = %1: must be up or down").arg(milling), kExitBadInput);
  s.direction = milling == "up" ? MillingDirection::Up : MillingDirection::Down;
  return s;
}

// The value of a per-record flag for the record-th record file: one value for all, or one per record.
double perRecord(const QCommandLineParser& parser, const QString& name, int record, int records, double min,
                 double max) {
  const QStringList values = parser.values(name);
  if (values.size() != 1 && values.size() != records)
    throw CliError(QString("--%1: given %2 times for %3 record file(s): give it once, or once per record")
                       .arg(name)
                       .arg(values.size())
                       .arg(records),
                   kExitBadInput);
  const QString text = values.size() == 1 ? values[0] : values[record];
  bool ok = false;
  const double v = text.toDouble(&ok);
  if (!ok || !(v >= min && v <= max))
    throw CliError(QString("--%1 = %2: must be a number in [%3, %4]").arg(name, text).arg(min).arg(max), kExitBadInput);
  return v;
}

enum class CutFile { MeanForces, RecordCsv, RecordUff };

CutFile kindOf(std::string_view bytes) {
  if (isUniversalFile(bytes)) return CutFile::RecordUff;
  return isForceRecordCsv(bytes) ? CutFile::RecordCsv : CutFile::MeanForces;
}

ForceRecord readRecord(CutFile kind, std::string_view bytes, const std::string& source) {
  return kind == CutFile::RecordUff ? readForceRecordUff(bytes, source) : readForceRecordCsv(bytes, source);
}

std::vector<TestCut> readCuts(const QCommandLineParser& parser, const QStringList& files) {
  std::vector<std::string> contents;
  std::vector<CutFile> kinds;
  for (const QString& file : files) {
    try {
      contents.push_back(readBoundedFile(file, kTestCutFileLimit).toStdString());
    } catch (const InvalidInput& e) {
      throw CliError(QString("%1: %2").arg(file, e.what()), kExitBadInput);
    }
    kinds.push_back(kindOf(contents.back()));
  }
  const auto records =
      static_cast<int>(std::count_if(kinds.begin(), kinds.end(), [](CutFile k) { return k != CutFile::MeanForces; }));
  std::vector<TestCut> cuts;
  int record = 0;
  for (std::size_t i = 0; i < contents.size(); ++i) {
    const std::string source = files[static_cast<qsizetype>(i)].toStdString();
    try {
      if (kinds[i] != CutFile::MeanForces) {
        const double rpm = perRecord(parser, "speed", record, records, 1e-3, 1e6);
        const double feed_mm = perRecord(parser, "feed", record, records, 1e-6, 10.0);
        ++record;
        cuts.push_back(meanOverRevolutions(readRecord(kinds[i], contents[i], source), rpm, feed_mm / 1000.0, source));
      } else {
        for (const TestCut& c : readMeanForcesCsv(contents[i], source)) cuts.push_back(c);
      }
    } catch (const InvalidInput& e) {
      throw CliError(QString::fromStdString(e.what()), kExitBadInput);
    }
  }
  return cuts;
}

QJsonObject coefficientsJson(const CuttingCoefficients& k) {
  return {{"Kt_N_mm2", k.Ktc_pa * 1e-6},      {"Krc_N_mm2", k.Krc_pa * 1e-6},     {"Ka_N_mm2", k.Kac_pa * 1e-6},
          {"Kte_N_mm", k.Kte_n_per_m * 1e-3}, {"Kre_N_mm", k.Kre_n_per_m * 1e-3}, {"Kae_N_mm", k.Kae_n_per_m * 1e-3}};
}

}  // namespace

int runCoefficientsCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Cutting coefficients from test cuts (average-force method).");
  parser.addHelpOption();
  parser.addPositionalArgument(
      "FILE",
      "Mean forces per cut (CSV), or one cut's dynamometer record: a CSV, or a universal file of datasets 58 "
      "type 1 (time responses of Fx, Fy, Fz). At most 256 MB.",
      "FILE...");
  parser.addOptions({
      {"diameter", "Cutter diameter [mm].", "MM"},
      {"teeth", "Number of teeth, 1..100.", "N"},
      {"depth", "Axial depth of cut of the test cuts [mm].", "MM"},
      {"immersion", "Radial immersion a_e/D in (0, 1]. Default 1 (slotting).", "A_D"},
      {"milling", "up or down (partial immersion). Default down.", "up|down"},
      {"speed", "Spindle speed of a record [rpm]: once, or once per record file.", "RPM"},
      {"feed", "Feed per tooth of a record [mm]: once, or once per record file.", "MM_PER_TOOTH"},
  });
  parseArguments(parser, arguments);
  const QStringList files = parser.positionalArguments();
  if (files.isEmpty()) throw CliError("coefficients: give at least one test-cut FILE", kExitBadInput);
  const TestCutSetup setup = readSetup(parser);
  const std::vector<TestCut> cuts = readCuts(parser, files);
  CoefficientFit fit;
  try {
    fit = fitCuttingCoefficients(setup, cuts);
  } catch (const InvalidInput& e) {
    throw CliError(QString("coefficients: %1").arg(e.what()), kExitBadInput);
  }
  QJsonObject out = coefficientsJson(fit.coefficients);
  out.insert("Kr", fit.Kr());
  out.insert("ci95", coefficientsJson(fit.half_width_95));
  out.insert("r2", QJsonObject{{"x", fit.lines[0].r2}, {"y", fit.lines[1].r2}, {"z", fit.lines[2].r2}});
  QJsonArray residuals;
  for (std::size_t i = 0; i < cuts.size(); ++i)
    residuals.append(QJsonObject{{"feed_mm_per_tooth", cuts[i].feed_per_tooth_m * 1e3},
                                 {"x", fit.lines[0].residuals_n[i]},
                                 {"y", fit.lines[1].residuals_n[i]},
                                 {"z", fit.lines[2].residuals_n[i]}});
  out.insert("residuals_N", residuals);
  out.insert("cuts", static_cast<qint64>(cuts.size()));
  printJson(out);
  return kExitOk;
}

}  // namespace mx::app
