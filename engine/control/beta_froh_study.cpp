#include "control/beta_froh_study.h"

#include <cmath>
#include <string>

namespace mx {

namespace {

// argmin of one reading over the admissible betas, as sweepBeta does for the plant-samples reading, and whether it
// is a one-point dip.
void argmin(const BetaSweepResult& sweep, double isolated_ratio, BetaFrohReadingResult& r) {
  const auto admissible = [&](std::size_t i) {
    return !sweep.unstable_zero[i] && sweep.completed[i] && std::isfinite(r.Jc_N_s[i]);
  };
  std::size_t best = 0;
  for (std::size_t i = 0; i < sweep.beta.size(); ++i) {
    if (!admissible(i)) continue;
    if (!r.found || r.Jc_N_s[i] < r.best_Jc_N_s) {
      r.found = true;
      r.best_beta = sweep.beta[i];
      r.best_Jc_N_s = r.Jc_N_s[i];
      best = i;
    }
  }
  if (!r.found) return;
  const auto above = [&](std::size_t i) {
    return admissible(i) && r.Jc_N_s[i] > (1.0 + isolated_ratio) * r.best_Jc_N_s;
  };
  const bool has_left = best > 0 && admissible(best - 1),
             has_right = best + 1 < sweep.beta.size() && admissible(best + 1);
  r.isolated_minimum = (has_left || has_right) && (!has_left || above(best - 1)) && (!has_right || above(best + 1));
}

AdaptiveControlSettings withTauC(const AdaptiveControlSettings& base, double tau_c_s) {
  AdaptiveControlSettings s = base;
  s.process.process_time_constant_s = tau_c_s;
  return s;
}

double firstSpindlePeriod(const AdaptiveControlSettings& s) {
  if (s.workpiece.steps.empty()) throw InvalidInput("beta-FROH study: the workpiece has no depth steps");
  return spindlePeriod(stepProcess(s.process, s.workpiece.steps.front()));
}

}  // namespace

const char* jcReadingName(JcReading reading) {
  return reading == JcReading::PlantSamples ? "plant_samples" : "reference_model";
}

std::vector<double> betaFrohStudyTauC(double T) {
  return {T / 16.0, T / 8.0, T / 6.0, T / 5.0, T / 4.0, T / 3.0, T / 2.0, T, 2.0 * T};
}

double firstOrderZeroThreshold(double tau_c_s, double T) {
  const double a = std::exp(-T / tau_c_s), c = tau_c_s * (1.0 - a) / T;
  return -(1.0 - a) / (2.0 * (1.0 - c));
}

double tauCForZeroThreshold(const AdaptiveControlSettings& settings, double target_beta) {
  if (!(target_beta > -1.0 && target_beta < -0.5))
    throw InvalidInput("beta-FROH study: target threshold = " + std::to_string(target_beta) +
                       ": must be in (-1, -0.5), the range of the zero threshold over tau_c");
  const double T = firstSpindlePeriod(settings);
  // The threshold falls monotonically with tau_c (-(1-a)/(2(1-c)) from -1/2 to -1): bisect on log tau_c.
  double lo = std::log(T * 1e-3), hi = std::log(T * 1e3);
  const auto f = [&](double log_tau) {
    return closedLoopZeroThreshold(withTauC(settings, std::exp(log_tau))) - target_beta;
  };
  if (!(f(lo) > 0.0 && f(hi) < 0.0))
    throw InvalidInput("beta-FROH study: no tau_c in [T/1000, 1000 T] gives the threshold " +
                       std::to_string(target_beta));
  while (hi - lo > 1e-12) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

BetaFrohStudyResult betaFrohStudy(const AdaptiveControlSettings& base, const BetaFrohStudySettings& study,
                                  const JobControl& job) {
  validateAdaptiveControlSettings(base);
  BetaFrohStudyResult r;
  const double T = firstSpindlePeriod(base);
  r.sampling_period_s = T;
  r.default_tau_c_s = processTimeConstant(stepProcess(base.process, base.workpiece.steps.front()));
  const std::vector<double> taus = study.tau_c_s.empty() ? betaFrohStudyTauC(T) : study.tau_c_s;
  for (double tau : taus)
    if (!(tau > 0.0) || !std::isfinite(tau))
      throw InvalidInput("beta-FROH study: tau_c = " + std::to_string(tau) + " s: must be finite and > 0");
  if (!(study.best_beta_tolerance >= 0.0 && study.threshold_tolerance >= 0.0 && study.isolated_ratio >= 0.0))
    throw InvalidInput("beta-FROH study: the tolerances must be >= 0");
  r.beta = betaGrid(study.sweep.from, study.sweep.to, study.sweep.step);

  const double n = static_cast<double>(taus.size());
  for (std::size_t k = 0; k < taus.size(); ++k) {
    if (job.cancelled()) throw Cancelled();
    const AdaptiveControlSettings s = withTauC(base, taus[k]);
    BetaFrohStudyRow row;
    row.tau_c_s = taus[k];
    row.tau_c_over_T = taus[k] / T;
    row.threshold_beta = closedLoopZeroThreshold(s);
    row.threshold_found = row.threshold_beta > -1.0;
    row.first_order_threshold_beta = firstOrderZeroThreshold(taus[k], T);
    row.threshold_near_paper =
        row.threshold_found && std::abs(row.threshold_beta - study.paper_threshold_beta) <= study.threshold_tolerance;

    JobControl inner;
    inner.cancel = job.cancel;
    if (job.progress) inner.progress = [&job, k, n](double f) { job.report((static_cast<double>(k) + f) / n); };
    const BetaSweepResult sweep = sweepBeta(s, study.sweep, inner);
    row.unstable_zero = sweep.unstable_zero;
    row.completed = sweep.completed;
    for (JcReading reading : kJcReadings) {
      BetaFrohReadingResult rr;
      rr.reading = reading;
      rr.Jc_N_s = reading == JcReading::PlantSamples ? sweep.Jc_N_s : sweep.Jc_model_N_s;
      argmin(sweep, study.isolated_ratio, rr);
      rr.near_paper = rr.found && row.threshold_near_paper &&
                      std::abs(rr.best_beta - study.paper_best_beta) <= study.best_beta_tolerance;
      if (rr.near_paper) r.matches.push_back({k, reading, rr.isolated_minimum});
      row.readings.push_back(std::move(rr));
    }
    r.rows.push_back(std::move(row));
  }

  r.tau_c_at_paper_threshold_s = tauCForZeroThreshold(base, study.paper_threshold_beta);
  // A higher threshold (closer to -1/2) belongs to a smaller tau_c.
  r.tau_c_near_paper_threshold_lo_s =
      tauCForZeroThreshold(base, std::min(-0.5 - 1e-9, study.paper_threshold_beta + study.threshold_tolerance));
  r.tau_c_near_paper_threshold_hi_s =
      tauCForZeroThreshold(base, std::max(-1.0 + 1e-9, study.paper_threshold_beta - study.threshold_tolerance));
  return r;
}

}  // namespace mx
