// millexpert-cli control PROJECT --beta B [--csv FILE] [--csv-continuous FILE]
// millexpert-cli control PROJECT --sweep-beta FROM:TO:STEP
// millexpert-cli control PROJECT --beta-study [--tau-c-ms LIST | FROM:TO:STEP] [--sweep-beta FROM:TO:STEP]
// Adaptive force control under beta-FROH (2006 paper, section 4; the project's "control" section,
// control_request.h): the closed loop over the workpiece depth profile, simulated with the continuous
// plant integrated between samples (CVODE).
//   --beta prints {"beta", "overshoot_pct": [...], "settling_time_s", "Jc", "unstable_zero",
//     "max_force_N", "min_feed_mm_s", "max_feed_mm_s"} plus "force_reference_N", "reference_binding",
//     "sampling_period_s", "tau_c_ms", "threshold_beta", "completed", "duration_s", "samples",
//     "rls_resets", "poles", "zeros" ([re, im] of H_beta of the true plant at the first depth).
//     Without --beta: the project's control.beta.
//     Every run adds "sample_period" ("spindle" | "rule4", control.sample_period or --sample-period),
//     "rule4_periods", "sampling_period_min_s", "sampling_period_max_s" and "spindle_revolutions" (the samples a
//     once-per-revolution loop would take); with control.programme (Pareto paper, Fig. 6), "programme": the
//     per-point summary and the feed and force history (control_programme_json.h).
//   --csv FILE: one row per sample (t, reference, model, sampled force, error, feed, depth, estimates);
//   --csv-continuous FILE: the continuous output between samples (force, its interpolation, feeds).
//   --sweep-beta prints {"beta": [...], "Jc": [...], "best_beta"} plus "unstable_zero": [...],
//     "threshold_beta", "found" (false: no beta with stable zeros completed the workpiece).
//   --beta-study (beta_froh_study.h) prints {"sampling_period_s", "default_tau_c_ms", "paper": {...}, "beta": [...],
//     "rows": [{"tau_c_ms", "tau_c_over_T", "threshold_beta", "first_order_threshold_beta", "threshold_near_paper",
//     "unstable_zero": [...], "readings": [{"reading": "plant_samples" | "reference_model", "best_beta", "best_Jc",
//     "near_paper", "isolated_minimum", "Jc": [...]}]}],
//     "matches_paper": [{"tau_c_ms", "tau_c_over_T", "reading", "isolated_minimum"}],
//     "tau_c_at_paper_threshold_ms", "tau_c_near_paper_threshold_ms": [lo, hi]}; the beta grid is --sweep-beta
//     (default -1:1:0.05), the tau_c values --tau-c-ms (default T/16, T/8, T/6, T/5, T/4, T/3, T/2, T, 2T).
// Exit 2: bad project, section or flags; exit 1: the simulation failed.
#include <QJsonArray>

#include "cli/cli_application.h"
#include "cli/cli_commands.h"
#include "cli/cli_support.h"
#include "cli/control_programme_json.h"
#include "cli/output_paths.h"
#include "control/beta_froh_study.h"
#include "control/beta_sweep.h"
#include "core/invalid_input.h"
#include "document/shortened_text.h"
#include "services/control_request.h"

namespace mx::app {

namespace {

QJsonArray complexJson(const Roots& roots) {
  QJsonArray out;
  for (const std::complex<double>& z : roots) out.append(QJsonArray{z.real(), z.imag()});
  return out;
}

// Each beta is a whole closed-loop run (about 10 ms for the 2006 workpiece, up to seconds for a long
// one): 400 steps, a step of 0.005 over [-1, 1], is the finest sweep.
constexpr int kMaxBetaSweepSteps = 400;

BetaSweepSettings parseSweep(const QString& text) {
  const QStringList parts = text.split(':');
  bool ok[3] = {false, false, false};
  BetaSweepSettings s;
  if (parts.size() == 3) {
    s.from = parts[0].toDouble(&ok[0]);
    s.to = parts[1].toDouble(&ok[1]);
    s.step = parts[2].toDouble(&ok[2]);
  }
  if (!ok[0] || !ok[1] || !ok[2] || !(s.from >= -1.0 && s.from <= s.to && s.to <= 1.0 && s.step > 0.0) ||
      (s.to - s.from) / s.step > kMaxBetaSweepSteps)
    throw CliError(QString("--sweep-beta = %1: expected FROM:TO:STEP with -1 <= FROM <= TO <= 1, STEP > 0 and at "
                           "most %2 steps (each a closed-loop run)")
                       .arg(quoted(text))
                       .arg(kMaxBetaSweepSteps),
                   kExitBadInput);
  return s;
}

// The study runs one sweep per tau_c: at most 4000 closed-loop runs (about a minute on 2 cores).
constexpr int kMaxBetaStudyRuns = 4000;
constexpr int kMaxStudyTauC = 50;
constexpr double kMaxTauCMs = 10000.0;

std::vector<double> parseTauCMs(const QString& text) {
  std::vector<double> ms;
  bool ok = true;
  const QStringList range = text.split(':');
  if (range.size() == 3) {
    bool o[3] = {false, false, false};
    const double from = range[0].toDouble(&o[0]), to = range[1].toDouble(&o[1]), step = range[2].toDouble(&o[2]);
    ok = o[0] && o[1] && o[2] && from > 0.0 && from <= to && step > 0.0 && (to - from) / step < kMaxStudyTauC;
    for (int i = 0; ok && from + i * step <= to * (1.0 + 1e-12); ++i) ms.push_back(from + i * step);
  } else {
    for (const QString& part : text.split(',')) {
      bool o = false;
      ms.push_back(part.trimmed().toDouble(&o));
      ok = ok && o;
    }
  }
  ok = ok && !ms.empty() && static_cast<int>(ms.size()) <= kMaxStudyTauC;
  for (double v : ms) ok = ok && v > 0.0 && v <= kMaxTauCMs;
  if (!ok)
    throw CliError(QString("--tau-c-ms = %1: expected a comma-separated list or FROM:TO:STEP of 1 to %2 values, each "
                           "in (0, %3] ms")
                       .arg(quoted(text))
                       .arg(kMaxStudyTauC)
                       .arg(kMaxTauCMs),
                   kExitBadInput);
  return ms;
}

QJsonObject betaStudyJson(const BetaFrohStudySettings& settings, const BetaFrohStudyResult& r) {
  QJsonArray betas, rows, matches;
  for (double b : r.beta) betas.append(b);
  for (const BetaFrohStudyRow& row : r.rows) {
    QJsonArray readings, unstable;
    for (bool u : row.unstable_zero) unstable.append(u);
    for (const BetaFrohReadingResult& rr : row.readings) {
      QJsonArray jc;
      for (double v : rr.Jc_N_s) jc.append(jsonNumberOrNull(v));
      readings.append(QJsonObject{{"reading", jcReadingName(rr.reading)},
                                  {"best_beta", rr.found ? QJsonValue(rr.best_beta) : QJsonValue()},
                                  {"best_Jc", rr.found ? QJsonValue(rr.best_Jc_N_s) : QJsonValue()},
                                  {"near_paper", rr.near_paper},
                                  {"isolated_minimum", rr.isolated_minimum},
                                  {"Jc", jc}});
    }
    rows.append(QJsonObject{{"tau_c_ms", row.tau_c_s * 1e3},
                            {"tau_c_over_T", row.tau_c_over_T},
                            {"threshold_beta", row.threshold_found ? QJsonValue(row.threshold_beta) : QJsonValue()},
                            {"first_order_threshold_beta", row.first_order_threshold_beta},
                            {"threshold_near_paper", row.threshold_near_paper},
                            {"unstable_zero", unstable},
                            {"readings", readings}});
  }
  for (const BetaFrohStudyMatch& m : r.matches)
    matches.append(QJsonObject{{"tau_c_ms", r.rows[m.row].tau_c_s * 1e3},
                               {"tau_c_over_T", r.rows[m.row].tau_c_over_T},
                               {"reading", jcReadingName(m.reading)},
                               {"isolated_minimum", m.isolated_minimum}});
  return {{"sampling_period_s", r.sampling_period_s},
          {"default_tau_c_ms", r.default_tau_c_s * 1e3},
          {"paper", QJsonObject{{"best_beta", settings.paper_best_beta},
                                {"best_beta_tolerance", settings.best_beta_tolerance},
                                {"threshold_beta", settings.paper_threshold_beta},
                                {"threshold_tolerance", settings.threshold_tolerance},
                                {"isolated_ratio", settings.isolated_ratio}}},
          {"beta", betas},
          {"rows", rows},
          {"matches_paper", matches},
          {"tau_c_at_paper_threshold_ms", r.tau_c_at_paper_threshold_s * 1e3},
          {"tau_c_near_paper_threshold_ms",
           QJsonArray{r.tau_c_near_paper_threshold_lo_s * 1e3, r.tau_c_near_paper_threshold_hi_s * 1e3}}};
}

void writeSamples(const QString& path, const ClosedLoopResult& r) {
  writeTextFileAtomically("--csv", path, [&](QTextStream& out) {
    const std::size_t n_theta = r.samples.empty() ? 0 : r.samples.front().theta.size();
    out << "t_s,reference_N,model_N,force_N,error_N,feed_mm_s,depth_mm,rls_reset,model_zeros_followed";
    for (std::size_t k = 0; k < n_theta; ++k) out << ",theta" << k + 1;
    out << '\n';
    for (const ClosedLoopSample& s : r.samples) {
      out << s.t << ',' << s.reference_N << ',' << s.model_N << ',' << s.force_N << ',' << s.error_N << ','
          << s.feed_m_s * 1e3 << ',' << s.depth_m * 1e3 << ',' << int(s.rls_reset) << ','
          << int(s.model_zeros_followed);
      for (std::size_t k = 0; k < n_theta; ++k) out << ',' << (k < s.theta.size() ? s.theta[k] : 0.0);
      out << '\n';
    }
  });
}

void writeContinuous(const QString& path, const ClosedLoopResult& r) {
  writeTextFileAtomically("--csv-continuous", path, [&](QTextStream& out) {
    out << "t_s,force_N,force_interpolated_N,feed_command_mm_s,feed_actual_mm_s,position_mm,depth_mm\n";
    for (const ClosedLoopDensePoint& d : r.dense)
      out << d.t << ',' << d.force_N << ',' << d.interpolated_N << ',' << d.feed_command_m_s * 1e3 << ','
          << d.feed_actual_m_s * 1e3 << ',' << d.position_m * 1e3 << ',' << d.depth_m * 1e3 << '\n';
  });
}

}  // namespace

int runControlCommand(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Adaptive force control under beta-FROH (2006 paper, section 4).");
  parser.addHelpOption();
  parser.addOptions({
      {"beta", "FROH gain beta in [-1, 1]. Default: the project's control.beta.", "B"},
      {"csv", "Write the sampled signals (one row per spindle period) to FILE.", "FILE"},
      {"csv-continuous", "Write the continuous output between samples to FILE.", "FILE"},
      {"sweep-beta", "J_c(beta) over FROM:TO:STEP instead of one run.", "FROM:TO:STEP"},
      {"sample-period", "spindle or rule4 (Pareto paper, Rule 4). Default: control.sample_period.", "RULE"},
      {"rule4-periods", "k of Rule 4, an integer in [1, 100]. Default: control.rule4_periods.", "K"},
      {"beta-study", "J_c(beta) and the zero threshold for several tau_c (figure 13 and the -0.6 of section 4)."},
      {"tau-c-ms", "With --beta-study: tau_c values [ms], a list A,B,... or FROM:TO:STEP. Default: T/16 ... 2T.",
       "LIST"},
  });
  const QString path = parseSubcommand(parser, arguments);
  const std::optional<double> beta = numberOption(parser, "beta", -1.0, 1.0);
  std::optional<BetaSweepSettings> sweep;
  if (parser.isSet("sweep-beta")) sweep = parseSweep(parser.value("sweep-beta"));
  const bool study = parser.isSet("beta-study");
  std::vector<double> tau_c_ms;
  if (parser.isSet("tau-c-ms")) {
    if (!study) throw CliError("--tau-c-ms: needs --beta-study", kExitBadInput);
    tau_c_ms = parseTauCMs(parser.value("tau-c-ms"));
  }
  if (study) {
    for (const char* flag : {"beta", "csv", "csv-continuous"})
      if (parser.isSet(flag))
        throw CliError(QString("--%1: not allowed with --beta-study (it runs a grid of beta)").arg(flag),
                       kExitBadInput);
    const BetaSweepSettings grid = sweep.value_or(BetaSweepSettings{-1.0, 1.0, 0.05, 0});
    const double runs = (std::floor((grid.to - grid.from) / grid.step + 1e-9) + 2.0) *
                        static_cast<double>(tau_c_ms.empty() ? betaFrohStudyTauC(1.0).size() : tau_c_ms.size());
    if (runs > kMaxBetaStudyRuns)
      throw CliError(QString("--beta-study: %1 beta values x tau_c values = %2 closed-loop runs: at most %3; "
                             "coarsen --sweep-beta or shorten --tau-c-ms")
                         .arg(std::floor((grid.to - grid.from) / grid.step + 1e-9) + 1.0)
                         .arg(runs)
                         .arg(kMaxBetaStudyRuns),
                     kExitBadInput);
  }
  const Project project =
      OutputPaths().outputOption(parser, "csv").outputOption(parser, "csv-continuous").loadProject(path);
  ControlRequest request = controlRequestFromProject(project);
  AdaptiveControlSettings& s = request.settings;
  if (beta) s.beta = *beta;
  if (parser.isSet("sample-period")) {
    const QString rule = parser.value("sample-period");
    if (rule != "spindle" && rule != "rule4")
      throw CliError(QString("--sample-period = %1: must be one of spindle, rule4").arg(quoted(rule)), kExitBadInput);
    s.sample_period = rule == "rule4" ? SamplePeriodRule::Rule4 : SamplePeriodRule::Spindle;
  }
  if (const std::optional<int> k = integerOption(parser, "rule4-periods", 1, 100)) s.rule4_periods = *k;
  const double threshold = closedLoopZeroThreshold(s);

  QJsonObject out;
  try {
    if (study) {
      BetaFrohStudySettings settings;
      if (sweep) settings.sweep = *sweep;
      for (double ms : tau_c_ms) settings.tau_c_s.push_back(ms * 1e-3);
      out = betaStudyJson(settings, betaFrohStudy(s, settings));
    } else if (sweep) {
      const BetaSweepResult r = sweepBeta(s, *sweep);
      QJsonArray betas, jc, unstable;
      for (std::size_t i = 0; i < r.beta.size(); ++i) {
        betas.append(r.beta[i]);
        jc.append(jsonNumberOrNull(r.Jc_N_s[i]));
        unstable.append(static_cast<bool>(r.unstable_zero[i]));
      }
      out = {{"beta", betas},
             {"Jc", jc},
             {"best_beta", r.found ? QJsonValue(r.best_beta) : QJsonValue()},
             {"best_Jc", r.found ? QJsonValue(r.best_Jc_N_s) : QJsonValue()},
             {"found", r.found},
             {"unstable_zero", unstable},
             {"threshold_beta", threshold}};
    } else {
      const ClosedLoopResult r = simulateAdaptiveForceControl(s);
      const ClosedLoopMetrics& m = r.metrics;
      QJsonArray overshoot;
      for (const DepthStepMetrics& step : m.steps) overshoot.append(step.overshoot_pct);
      out = {{"beta", s.beta},
             {"overshoot_pct", overshoot},
             {"settling_time_s", m.settling_time_s},
             {"Jc", m.Jc_N_s},
             {"unstable_zero", m.unstable_zero},
             {"max_force_N", m.max_force_N},
             {"min_feed_mm_s", m.min_feed_m_s * 1e3},
             {"max_feed_mm_s", m.max_feed_m_s * 1e3},
             {"force_reference_N", s.force_reference_N},
             {"reference_binding", QString::fromStdString(request.reference.binding)},
             {"sampling_period_s", r.sampling_period_s},
             {"tau_c_ms", r.tau_c_s * 1e3},
             {"threshold_beta", threshold},
             {"completed", m.completed},
             {"duration_s", m.duration_s},
             {"samples", m.samples},
             {"rls_resets", m.rls_resets},
             {"poles", complexJson(r.plant.poles())},
             {"zeros", complexJson(r.plant.zeros())}};
      addSamplingPeriodJson(s, r, out);
      if (request.programme) out.insert("programme", programmeJson(request, r));
      if (parser.isSet("csv")) writeSamples(parser.value("csv"), r);
      if (parser.isSet("csv-continuous")) writeContinuous(parser.value("csv-continuous"), r);
    }
  } catch (const InvalidInput& e) {
    throw CliError(QString("control: %1").arg(e.what()), kExitBadInput);
  } catch (const CliError&) {
    throw;
  } catch (const std::exception& e) {
    throw CliError(QString("control: the simulation failed: %1").arg(e.what()), kExitComputationFailed);
  }
  printJson(out);
  return kExitOk;
}

}  // namespace mx::app
